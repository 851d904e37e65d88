using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes the files of one planned view from its raw readback: colour with straight alpha, and the depth, normal
    /// and mask images its split asks for, under the write session's working folder. Depth is written in output units:
    /// the depth pass's Unity-unit z times the plan's normalisation scale, like the poses. Thread-safe: the capture calls it
    /// from several worker threads at once, one view each. The pixel arrays between post-processing and encoding are
    /// kept per thread and reused from view to view (Unity's collector is not generational: 6.4 MB of garbage per
    /// 800×800 view would be paid in full); only the encoded files are new arrays.
    /// </summary>
    public sealed class ViewFileWriter
    {
        readonly DatasetWriteSession _session;
        readonly Background _background;
        readonly ExrEncoder _encodeExr;
        readonly double _depthScale;
        readonly bool _backgroundIsClear;
        readonly ExposurePlan _exposure;
        readonly MattingTally _matting = new MattingTally();
        readonly HashSet<string> _createdFolders = new HashSet<string>(StringComparer.Ordinal);
        int _clampedDepthPixels;
        long _writeTicks, _encodeTicks;
        int _viewsWritten;

        /// <summary>One worker thread's pixel arrays, replaced only when the view size changes.</summary>
        sealed class Scratch
        {
            public byte[] Rgba = new byte[0], Mask = new byte[0], Rgb = new byte[0];
            public ushort[] Millimetres = new ushort[0], Ids = new ushort[0];
            public byte[] MaterialRgba = new byte[0], MaterialAlpha = new byte[0];
            public float[] MaterialValues = new float[0], MaterialExr = new float[0];
        }

        [ThreadStatic] static Scratch scratch;

        /// <param name="plan">The views' plan: its settings (background) and its normalisation (depth scale).</param>
        /// <param name="encodeExr">Needed only when a split writes EXR files; null otherwise.</param>
        public ViewFileWriter(CapturePlan plan, DatasetWriteSession session, ExrEncoder encodeExr)
        {
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            _session = session ?? throw new ArgumentNullException(nameof(session));
            _background = BackgroundOf(plan.Settings);
            _depthScale = plan.Normalisation.Scale;
            // A sky is rendered into both colour halves (no clear shows): nothing outside the geometry is "background".
            _backgroundIsClear = plan.Settings.Background == null || !plan.Settings.Background.Sky;
            _encodeExr = encodeExr;
            _exposure = ExposurePlan.Of(plan.Settings);
        }

        /// <summary>Output units per Unity unit of depth (the normalisation's scale s).</summary>
        public double DepthScale => _depthScale;

        /// <summary>Depth pixels farther than a 16-bit PNG holds (65.535 output units), clamped so far: reported once per run.</summary>
        public int ClampedDepthPixels => Volatile.Read(ref _clampedDepthPixels);

        /// <summary>
        /// What the difference matting could not explain, summed over the views written so far, and the views above the
        /// per-view threshold (<see cref="MattingDiagnostics"/>; Documentation~/capture.md, "Matting diagnostics").
        /// </summary>
        public MattingTally Matting => _matting;

        /// <summary>
        /// The capture's label table, needed when the plan writes id maps (settings <c>labels</c>): the semantic map is
        /// the instance ids mapped through <see cref="LabelTable.ClassOfInstance"/>. A dynamic capture may add objects to
        /// the table between time steps (<see cref="LabelTable.AddAppearing"/>), never while views are being written.
        /// </summary>
        public LabelTable Labels { get; set; }

        /// <summary>Views written so far, by all threads.</summary>
        public int ViewsWritten => Volatile.Read(ref _viewsWritten);

        /// <summary>Time spent in <see cref="Write"/>, summed over the threads that called it (a busy time, not wall time).</summary>
        public double WriteSeconds => Interlocked.Read(ref _writeTicks) / (double)Stopwatch.Frequency;

        /// <summary>The part of <see cref="WriteSeconds"/> spent in PNG encoding.</summary>
        public double PngEncodeSeconds => Interlocked.Read(ref _encodeTicks) / (double)Stopwatch.Frequency;

        /// <summary>
        /// Writes <paramref name="view"/>'s files. <paramref name="colour"/> carries colour (the black/white pair for
        /// <see cref="DifferenceMatting"/>, or one render whose alpha is the mask) and mask at the supersampled size; <paramref name="data"/> carries depth and normals (in the output world frame, or in Unity's with <see cref="RawFrame.NormalsInUnityWorld"/>), at
        /// that size or at the output size (supersampling 1). Either may be the same frame.
        /// </summary>
        public void Write(PlannedView view, RawFrame colour, RawFrame data) => Write(view, colour, data, countMatting: true);

        /// <summary>
        /// <see cref="Write(PlannedView, RawFrame, RawFrame)"/>, adding the colour's matting diagnostics to
        /// <see cref="Matting"/> only when <paramref name="countMatting"/>: false when the view's diagnostics were counted
        /// on another frame (<see cref="CountMatting"/>: a blurred or lens-resampled colour is not the render its mask belongs to).
        /// </summary>
        public void Write(PlannedView view, RawFrame colour, RawFrame data, bool countMatting)
        {
            long started = Stopwatch.GetTimestamp();
            long encoding = 0;
            var s = scratch ?? (scratch = new Scratch());
            int width = colour.OutputWidth, height = colour.OutputHeight, pixels = width * height;
            var wantsMask = view.Writes(DatasetFileKind.MaskPng);
            var rgba = Exact(ref s.Rgba, pixels * 4);
            var mask = wantsMask ? Exact(ref s.Mask, pixels) : null;
            if (colour.ColorOverBlack != null)
            {
                // Alpha from the two colour renders; the mask file is the mask pass's geometry coverage (pixels.md §3).
                var diagnostics = DifferenceMatting.Resolve(colour, rgba, _background, _backgroundIsClear);
                if (countMatting) _matting.Add(view.Split, view.Index, diagnostics);
                if (wantsMask) MaskEncoding.Encode(colour, mask);
            }
            else StraightAlpha.Resolve(colour, rgba, _background, mask);
            // Linear HDR colour (settings hdr): the same pair, before the clip and before exposure (HdrColour).
            if (view.Writes(DatasetFileKind.HdrExr)) Save(view, DatasetFileKind.HdrExr, Exr(HdrColour.Resolve(colour, _background), width, height, 4));
            if (_exposure != null && _exposure.Applies(view.Split))
            {
                // The last stage before encoding (exposure.md): the clean image first, then the same pixels scaled in linear light.
                if (view.Writes(DatasetFileKind.CleanColor)) Save(view, DatasetFileKind.CleanColor, Png(rgba, width, height, PngPixelFormat.Rgba8, ref encoding));
                var exposure = _exposure.For(view.Split, view.Index);
                ExposureWhiteBalance.ApplyRgba(rgba, exposure);
                Save(view, DatasetFileKind.Color, PngChunks.InsertExif(Png(rgba, width, height, PngPixelFormat.Rgba8, ref encoding), ExifExposure.Block(exposure.Ev)));
            }
            else Save(view, DatasetFileKind.Color, Png(rgba, width, height, PngPixelFormat.Rgba8, ref encoding));
            if (wantsMask) Save(view, DatasetFileKind.MaskPng, Png(mask, width, height, PngPixelFormat.Gray8, ref encoding));
            if (view.Writes(DatasetFileKind.RelitPng)) WriteRelit(view, colour, rgba, ref encoding);

            if (view.Writes(DatasetFileKind.DepthPng))
            {
                var millimetres = Exact(ref s.Millimetres, pixels);
                Interlocked.Add(ref _clampedDepthPixels, DepthEncoding.ToMillimetres(data, millimetres, _depthScale));
                long before = Stopwatch.GetTimestamp();
                var png = PngWriter.EncodeGray16(millimetres, width, height);
                encoding += Stopwatch.GetTimestamp() - before;
                Save(view, DatasetFileKind.DepthPng, png);
            }
            if (view.Writes(DatasetFileKind.DepthExr))
            {
                var metres = new float[pixels];
                DepthEncoding.ToMetres(data, metres, RowDirection.BottomRowFirst, _depthScale);
                Save(view, DatasetFileKind.DepthExr, Exr(metres, width, height, 1));
            }
            if (view.Writes(DatasetFileKind.NormalPng))
            {
                var rgb = Exact(ref s.Rgb, pixels * 3);
                NormalEncoding.Encode(data, rgb);
                Save(view, DatasetFileKind.NormalPng, Png(rgb, width, height, PngPixelFormat.Rgb8, ref encoding));
            }
            if (view.Writes(DatasetFileKind.NormalExr))
            {
                var normals = new float[pixels * 4];
                NormalEncoding.ToFloats(data, normals, RowDirection.BottomRowFirst);
                Save(view, DatasetFileKind.NormalExr, Exr(normals, width, height, 4));
            }
            if (view.Writes(DatasetFileKind.InstancePng) || view.Writes(DatasetFileKind.SemanticPng))
                encoding += WriteIds(view, colour, data, s);
            Interlocked.Add(ref _encodeTicks, encoding);
            Interlocked.Add(ref _writeTicks, Stopwatch.GetTimestamp() - started);
            Interlocked.Increment(ref _viewsWritten);
        }

        /// <summary>
        /// Relighting: the view under each lighting condition (<see cref="RawFrame.Relit"/>), through the colour stages of
        /// the view's own image — difference matting (or straight alpha from the view's mask), the linear HDR image — with
        /// the view's geometry (<see cref="RelitFrames"/>), so its alpha is the view's. Exposure and white balance are not
        /// applied: a relit image is ground truth for one light, compared across methods (Documentation~/maintainers/relighting.md).
        /// <paramref name="rgba"/> is the thread's colour array, free again once the view's image is encoded.
        /// </summary>
        void WriteRelit(PlannedView view, RawFrame colour, byte[] rgba, ref long encoding)
        {
            int width = colour.OutputWidth, height = colour.OutputHeight;
            foreach (var key in view.RelitKeys)
            {
                RawFrame relit = null;
                colour.Relit?.TryGetValue(key, out relit);
                var frame = RelitFrames.WithViewGeometry(key, relit, colour);
                if (frame.ColorOverBlack != null) DifferenceMatting.Resolve(frame, rgba, _background, _backgroundIsClear);
                else StraightAlpha.Resolve(frame, rgba, _background, null);
                SaveAs(DatasetLayout.RelitRelativePath(view.Split, view.Index, key, false), Png(rgba, width, height, PngPixelFormat.Rgba8, ref encoding));
                if (view.Writes(DatasetFileKind.RelitHdrExr))
                    SaveAs(DatasetLayout.RelitRelativePath(view.Split, view.Index, key, true), Exr(HdrColour.Resolve(frame, _background), width, height, 4));
            }
        }

        /// <summary>The instance and semantic maps (<see cref="IdMajority"/>) from whichever frame carries the id pass; returns the encoding ticks.</summary>
        long WriteIds(PlannedView view, RawFrame colour, RawFrame data, Scratch s)
        {
            var frame = colour.InstanceIds != null ? colour : data;
            if (frame.InstanceIds == null)
                throw new InvalidOperationException("This run writes instance/semantic maps but the view's frames carry no id pass (RawFrame.InstanceIds).");
            var labels = Labels ?? throw new InvalidOperationException("This run writes instance/semantic maps but no label table was given (ViewFileWriter.Labels).");
            var ids = Exact(ref s.Ids, frame.OutputWidth * frame.OutputHeight);
            long encoding = 0;
            if (view.Writes(DatasetFileKind.InstancePng))
            {
                IdMajority.Resolve(frame, ids);
                long before = Stopwatch.GetTimestamp();
                var png = PngWriter.EncodeGray16(ids, frame.OutputWidth, frame.OutputHeight);
                encoding += Stopwatch.GetTimestamp() - before;
                Save(view, DatasetFileKind.InstancePng, png);
            }
            if (view.Writes(DatasetFileKind.SemanticPng))
            {
                IdMajority.Resolve(frame, ids, labels.ClassOfInstance);
                long before = Stopwatch.GetTimestamp();
                var png = PngWriter.EncodeGray16(ids, frame.OutputWidth, frame.OutputHeight);
                encoding += Stopwatch.GetTimestamp() - before;
                Save(view, DatasetFileKind.SemanticPng, png);
            }
            return encoding;
        }

        /// <summary>
        /// Counts <paramref name="sharp"/>'s matting diagnostics (<see cref="MattingDiagnosis"/>) as the view's, for a view
        /// whose written colour is not the render its mask belongs to: <see cref="ViewPipeline"/> calls it with the wide
        /// render before a lens resamples it, and <see cref="WriteSharp"/> with the mid-pose render of a blurred view whose
        /// split writes no sharp image (issue 32, R4-3); the view is then written with <c>countMatting: false</c>. Does nothing for a frame without a colour pair (straight alpha).
        /// </summary>
        public void CountMatting(PlannedView view, RawFrame sharp)
        {
            if (sharp.ColorOverBlack == null) return;
            _matting.Add(view.Split, view.Index, MattingDiagnosis.Of(sharp, _backgroundIsClear));
        }

        /// <summary>
        /// Motion blur: writes the sharp colour render at the mid pose (<paramref name="sharp"/>, the same passes as a
        /// view without blur) as <c>r_i_sharp_0000.png</c>, resolved like the blurred image. Call it besides
        /// <see cref="Write(PlannedView, RawFrame, RawFrame, bool)"/>, whose colour is the sub-frame average
        /// (<see cref="SubFrameAccumulator"/>). With <paramref name="countMatting"/> the view's matting diagnostics are
        /// counted on this sharp render: taken from its own resolve when the split writes it, so the frame is not passed
        /// over twice, else by <see cref="CountMatting"/>.
        /// </summary>
        public void WriteSharp(PlannedView view, RawFrame sharp, bool countMatting = false)
        {
            if (!view.Writes(DatasetFileKind.SharpPng))
            {
                if (countMatting) CountMatting(view, sharp);
                return;
            }
            long started = Stopwatch.GetTimestamp();
            long encoding = 0;
            var s = scratch ?? (scratch = new Scratch());
            int width = sharp.OutputWidth, height = sharp.OutputHeight;
            var rgba = Exact(ref s.Rgba, width * height * 4);
            if (sharp.ColorOverBlack != null)
            {
                var diagnostics = DifferenceMatting.Resolve(sharp, rgba, _background, _backgroundIsClear);
                if (countMatting) _matting.Add(view.Split, view.Index, diagnostics);
            }
            else StraightAlpha.Resolve(sharp, rgba, _background, null);
            // With exposure, the sharp image is exposed like the blurred one, so that the two differ by the motion only.
            if (_exposure != null && _exposure.Applies(view.Split)) ExposureWhiteBalance.ApplyRgba(rgba, _exposure.For(view.Split, view.Index));
            Save(view, DatasetFileKind.SharpPng, Png(rgba, width, height, PngPixelFormat.Rgba8, ref encoding));
            Interlocked.Add(ref _encodeTicks, encoding);
            Interlocked.Add(ref _writeTicks, Stopwatch.GetTimestamp() - started);
        }

        /// <summary>
        /// The material passes (settings <c>materials</c>) of <paramref name="frame"/>, the view's colour render at its pose
        /// (the sharp, mid-pose one with motion blur; after the lens): per pass its EXR and PNG
        /// (<see cref="MaterialPassResolve"/>, <see cref="MaterialEncoding"/>), and the coverage PNG. Alpha is the colour
        /// image's coverage: the frame resolved as the colour image is, on a transparent background — the colour image's
        /// own alpha unless the settings' background is solid (then that image is opaque, and the passes still carry coverage);
        /// with a sky, which leaves the colour no coverage, the mask's.
        /// </summary>
        public void WriteMaterials(PlannedView view, RawFrame frame)
        {
            if (!MaterialPassFiles.Writes(view)) return;
            long started = Stopwatch.GetTimestamp();
            long encoding = 0;
            int width = frame.OutputWidth, height = frame.OutputHeight, pixels = width * height;
            var s = scratch ?? (scratch = new Scratch());
            var rgba = Exact(ref s.MaterialRgba, pixels * 4);
            var alpha = Exact(ref s.MaterialAlpha, pixels);
            // A sky is rendered into both colour halves, so the colour holds no coverage (alpha 1 everywhere): the mask's.
            if (!_backgroundIsClear) MaskEncoding.Encode(frame, alpha);
            else
            {
                if (frame.ColorOverBlack != null) DifferenceMatting.Resolve(frame, rgba, Background.Transparent, _backgroundIsClear);
                else StraightAlpha.Resolve(frame, rgba, Background.Transparent);
                for (var i = 0; i < pixels; i++) alpha[i] = rgba[i * 4 + 3];
            }
            foreach (var pass in MaterialPassFiles.All)
            {
                if (!view.Writes(pass.Exr)) continue;
                var straight = MaterialPassResolve.Resolve(frame, pass, alpha, Exact(ref s.MaterialValues, pixels * 4));
                Save(view, pass.Exr, Exr(MaterialEncoding.ExrOrder(straight, width, height, Exact(ref s.MaterialExr, pixels * 4)), width, height, 4));
                if (pass.Png is DatasetFileKind png)
                    Save(view, png, Png(MaterialEncoding.PngBytes(straight, alpha, pass.Encoding, rgba), width, height, PngPixelFormat.Rgba8, ref encoding));
            }
            Save(view, DatasetFileKind.MaterialCoveragePng, Png(MaterialPassResolve.Coverage(frame), width, height, PngPixelFormat.Gray8, ref encoding));
            Interlocked.Add(ref _encodeTicks, encoding);
            Interlocked.Add(ref _writeTicks, Stopwatch.GetTimestamp() - started);
        }

        static byte[] Png(byte[] pixels, int width, int height, PngPixelFormat format, ref long encoding)
        {
            long before = Stopwatch.GetTimestamp();
            var png = PngWriter.Encode(pixels, width, height, format);
            encoding += Stopwatch.GetTimestamp() - before;
            return png;
        }

        /// <summary>The thread's array of exactly <paramref name="length"/> elements (PngWriter takes exact lengths).</summary>
        static T[] Exact<T>(ref T[] array, int length)
        {
            if (array.Length != length) array = new T[length];
            return array;
        }

        byte[] Exr(float[] pixels, int width, int height, int channels)
        {
            if (_encodeExr == null)
                throw new InvalidOperationException("This run writes EXR files but no EXR encoder was given.");
            return _encodeExr(pixels, width, height, channels);
        }

        void Save(PlannedView view, DatasetFileKind kind, byte[] bytes) => SaveAs(DatasetLayout.RelativePath(view.Split, view.Index, kind), bytes);

        void SaveAs(string relativePath, byte[] bytes)
        {
            var path = _session.PathOf(relativePath);
            var folder = Path.GetDirectoryName(path);
            bool created;
            lock (_createdFolders) created = _createdFolders.Contains(folder);
            if (!created)
            {
                // Once per folder (a split's, or its depth/normal subfolder), not once per file.
                Directory.CreateDirectory(folder);
                lock (_createdFolders) _createdFolders.Add(folder);
            }
            File.WriteAllBytes(path, bytes);
        }

        /// <summary>The solid background is given as sRGB (#rrggbb in config files) and composited in linear light.</summary>
        static Background BackgroundOf(DatasetSettings settings)
        {
            var b = settings.Background;
            if (b == null || b.Transparent) return Background.Transparent;
            return Background.SolidSrgb(ToByte(b.R), ToByte(b.G), ToByte(b.B));
        }

        static byte ToByte(double c) => (byte)Math.Round(Math.Max(0, Math.Min(1, c)) * 255);
    }
}
