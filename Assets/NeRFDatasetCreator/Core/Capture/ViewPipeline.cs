namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-view stages of a capture, in their one order (Documentation~/maintainers/capture.md, "The per-view
    /// stages"): motion blur's sub-frame average (<see cref="SubFrameAverage"/>, summed on the render side as each
    /// sub-frame is read back) → lens resampling of the wide render into the distorted frame (<see cref="LensResampler"/>)
    /// → blurred or sharp image → <see cref="ViewFileWriter"/>: matting or straight alpha, k×k downsampling, the labels'
    /// majority rule, exposure and white balance, encoding. The Unity layer only turns its readback into
    /// <see cref="RawFrame"/>s and hands them here; the test suite's analytic datasets call the same object, so the order
    /// <c>dotnet test</c> runs is the capture's.
    /// Thread-safe like <see cref="ViewFileWriter"/>: the capture calls <see cref="Write"/> from several worker threads,
    /// one view each.
    /// </summary>
    public sealed class ViewPipeline
    {
        readonly LensResampler _lens;

        /// <summary>
        /// A run's pipeline: the plan's lens (<see cref="LensCapture.ResamplerFor"/>; none without one) and a
        /// <see cref="ViewFileWriter"/> on the write session.
        /// </summary>
        /// <param name="encodeExr">Needed only when a split writes EXR files; null otherwise.</param>
        /// <param name="labels">The capture's label table when the plan writes id maps (<see cref="ViewFileWriter.Labels"/>), else null.</param>
        public ViewPipeline(CapturePlan plan, DatasetWriteSession session, ExrEncoder encodeExr, LabelTable labels)
            : this(new ViewFileWriter(plan, session, encodeExr) { Labels = labels }, LensCapture.ResamplerFor(plan))
        {
        }

        /// <param name="files">The writer of the views' files.</param>
        /// <param name="lens">
        /// The resampler from the wide render, or null when the frames given to <see cref="Write"/> are at the output frame
        /// already (no lens, or a test that traces each distorted pixel's ray itself as an independent oracle of this stage).
        /// </param>
        public ViewPipeline(ViewFileWriter files, LensResampler lens)
        {
            Files = files ?? throw new System.ArgumentNullException(nameof(files));
            _lens = lens;
        }

        /// <summary>The file writer: the run's statistics (matting, clamped depth, writer time) are read from it at the end.</summary>
        public ViewFileWriter Files { get; }

        /// <summary>What the camera renders for a lens (the frames <see cref="Write"/> then takes), or null when the frames are at the output frame.</summary>
        public LensPinholeCover WideRender => _lens?.Wide;

        /// <summary>
        /// Writes one view's files from its raw frames. <paramref name="colour"/> is the colour render (the sharp one, at
        /// the mid pose, with motion blur) with mask and label ids; <paramref name="data"/> carries depth and normals — the
        /// same object as one of the colour frames, or a frame of its own at the output size; <paramref name="blurred"/>,
        /// with motion blur, is the sub-frame average (<see cref="SubFrameAverage"/>), written as the image while the
        /// sharp one goes beside it (<see cref="ViewFileWriter.WriteSharp"/>). With a lens all are wide renders.
        /// </summary>
        public void Write(PlannedView view, RawFrame colour, RawFrame data, RawFrame blurred = null)
        {
            // The matting diagnostics need a colour pair and a mask of the same render: the sharp frame, before any
            // resampling. A blurred average or a resampled colour would show every moving or distorted edge as "stray
            // background" (issue 32, R4-3): a lens view is counted here, on its wide render, a blurred one on its sharp
            // render as that is written (WriteSharp), and neither is counted again as its image is written.
            var countApart = _lens != null || blurred != null;
            if (_lens != null) Files.CountMatting(view, colour);
            if (_lens != null)
            {
                // The wide frames resampled into the distorted ones, on this worker thread, into its reused arrays (the frames
                // are written out below, before the thread's next view). The sharp image of a blurred view gets arrays of its
                // own: the thread's would be the blurred one's. A data frame that is one of the colour frames is resampled
                // with it; one of its own reuses the thread's arrays only at another size than the colour's (else it would
                // share them with the colour frame's passes).
                var sharp = _lens.Resample(colour, reuseThreadBuffers: blurred == null);
                MaterialPassLens.Carry(_lens, colour, sharp);
                if (blurred != null)
                {
                    var distortedBlur = _lens.Resample(blurred, reuseThreadBuffers: true);
                    data = ReferenceEquals(data, blurred) ? distortedBlur
                        : ReferenceEquals(data, colour) ? sharp
                        : _lens.Resample(data, reuseThreadBuffers: data.Supersampling != blurred.Supersampling);
                    blurred = distortedBlur;
                }
                else data = ReferenceEquals(data, colour) ? sharp : _lens.Resample(data, reuseThreadBuffers: data.Supersampling != colour.Supersampling);
                // Relighting: each condition's wide colour into the distorted frame too, into arrays of its own.
                sharp.Relit = RelitFrames.Resampled(colour, relit => _lens.Resample(relit));
                colour = sharp;
            }
            // The material passes are of the colour render at the view's pose (the sharp one with motion blur), like depth and normals.
            Files.WriteMaterials(view, colour);
            if (blurred == null)
            {
                Files.Write(view, colour, data, countMatting: !countApart);
                return;
            }
            // Motion blur: the file_path image is the sub-frame average; the mid-pose render is the sharp image beside it.
            Files.Write(view, blurred, data, countMatting: false);
            Files.WriteSharp(view, colour, countMatting: _lens == null);
        }

        /// <summary>
        /// Motion blur's first stage, on the render side: the sum of one view's <paramref name="subFrames"/> colour pairs
        /// (<see cref="SubFrameAccumulator"/>, <paramref name="width"/> × <paramref name="height"/> samples), added as each
        /// sub-frame is read back — the next one renders into the same textures — and finished into the blurred frame's
        /// colour pair, which <see cref="Write"/> then takes as <c>blurred</c>.
        /// </summary>
        public static SubFrameAccumulator SubFrameAverage(int width, int height, int subFrames, double readout, bool gammaEncoded) =>
            new SubFrameAccumulator(width, height, subFrames, readout, gammaEncoded);
    }
}
