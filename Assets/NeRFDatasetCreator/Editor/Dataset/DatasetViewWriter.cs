using System.Collections.Generic;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The capture's worker-thread writer for datasets: wraps a view's readback arrays as Core's raw frames (no copy),
    /// marks its normals as Unity world normals (the encoders relabel them into the output world as they read them),
    /// and hands it to Core's <see cref="ViewFileWriter"/> — through a lens capture's <see cref="LensResampler"/> first
    /// (the wide render becomes the distorted frame; everything after it is unchanged).
    /// The consumer releases the view afterwards.
    /// </summary>
    sealed class DatasetViewWriter : IViewWriter
    {
        readonly IReadOnlyList<PlannedView> _views;
        readonly ViewFileWriter _files;
        readonly LensResampler _lens;

        /// <param name="views">The planned views in the order their poses were given to the capture.</param>
        /// <param name="lens">The plan's resampler (<see cref="LensCapture.ResamplerFor"/>), or null without a lens.</param>
        public DatasetViewWriter(IReadOnlyList<PlannedView> views, ViewFileWriter files, LensResampler lens = null)
        {
            _views = views;
            _files = files;
            _lens = lens;
        }

        public void Write(CapturedView view)
        {
            var colour = new RawFrame(view.Width, view.Height, view.Supersampling)
            {
                ColorOverBlack = view.ColorOverBlack,
                ColorOverWhite = view.ColorOverWhite,
                ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                Mask = view.Mask,
                MaskBytesPerPixel = 1,
            };
            var atOutputSize = view.DataWidth != view.Width || view.DataHeight != view.Height;
            var data = atOutputSize ? new RawFrame(view.DataWidth, view.DataHeight, 1) : colour;
            data.Depth = view.Depth;
            data.Normals = view.Normal;
            // The normal pass writes Unity world normals; the encoders relabel them as they read them.
            data.NormalsInUnityWorld = true;
            if (view.Labels != null) colour.InstanceIds = InstanceIds(view.Labels);
            // Motion blur: the file_path image is the sub-frame average; the mid-pose render is the sharp image beside it.
            RawFrame blurred = null;
            if (view.BlurredOverBlack != null)
            {
                blurred = new RawFrame(view.Width, view.Height, view.Supersampling)
                {
                    ColorOverBlack = view.BlurredOverBlack,
                    ColorOverWhite = view.BlurredOverWhite,
                    ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                    Mask = view.Mask,
                    MaskBytesPerPixel = 1,
                    InstanceIds = colour.InstanceIds,
                };
                if (!atOutputSize)
                {
                    blurred.Depth = data.Depth;
                    blurred.Normals = data.Normals;
                    blurred.NormalsInUnityWorld = true;
                    data = blurred;
                }
            }
            if (_lens != null)
            {
                // Stage 2 of the per-view stages (parallel.md): the wide frames resampled into the distorted ones, on this worker thread,
                // into its reused arrays (the frames are written out below, before the thread's next view). The sharp image of a
                // blurred view gets arrays of its own: the thread's would be the blurred one's.
                var sharp = _lens.Resample(colour, reuseThreadBuffers: blurred == null);
                if (blurred != null)
                {
                    var distortedBlur = _lens.Resample(blurred, reuseThreadBuffers: true);
                    data = ReferenceEquals(data, blurred) ? distortedBlur : _lens.Resample(data, reuseThreadBuffers: true);
                    blurred = distortedBlur;
                }
                else data = ReferenceEquals(data, colour) ? sharp : _lens.Resample(data, reuseThreadBuffers: true);
                colour = sharp;
            }
            if (blurred == null)
            {
                _files.Write(_views[view.ViewIndex], colour, data);
                return;
            }
            _files.Write(_views[view.ViewIndex], blurred, data);
            _files.WriteSharp(_views[view.ViewIndex], colour);
        }

        [System.ThreadStatic] static ushort[] ids;

        /// <summary>
        /// The instance id of each sample from the labels pass's bytes (low, high; <see cref="RendererLabelIds"/>), into this
        /// thread's buffer: the writer has encoded the maps before <see cref="ViewFileWriter.Write"/> returns.
        /// </summary>
        static ushort[] InstanceIds(byte[] labels)
        {
            var samples = labels.Length / 4;
            if (ids == null || ids.Length != samples) ids = new ushort[samples];
            for (var i = 0; i < samples; i++) ids[i] = (ushort)(labels[i * 4] | (labels[i * 4 + 1] << 8));
            return ids;
        }
    }
}
