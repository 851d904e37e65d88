using System;
using System.IO;
using System.Threading;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes the files of one planned view from its raw readback: colour with straight alpha, and the depth, normal
    /// and mask images its split asks for, under the write session's working folder. Depth is written in output units:
    /// the depth pass's Unity-unit z times the plan's normalisation scale, like the poses. Thread-safe: the capture calls it
    /// from several worker threads at once, one view each; scratch arrays are per call (a view's worth, freed with it).
    /// </summary>
    public sealed class ViewFileWriter
    {
        readonly DatasetWriteSession _session;
        readonly Background _background;
        readonly ExrEncoder _encodeExr;
        readonly double _depthScale;
        int _clampedDepthPixels;

        /// <param name="plan">The views' plan: its settings (background) and its normalisation (depth scale).</param>
        /// <param name="encodeExr">Needed only when a split writes EXR files; null otherwise.</param>
        public ViewFileWriter(CapturePlan plan, DatasetWriteSession session, ExrEncoder encodeExr)
        {
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            _session = session ?? throw new ArgumentNullException(nameof(session));
            _background = BackgroundOf(plan.Settings);
            _depthScale = plan.Normalisation.Scale;
            _encodeExr = encodeExr;
        }

        /// <summary>Output units per Unity unit of depth (the normalisation's scale s).</summary>
        public double DepthScale => _depthScale;

        /// <summary>Depth pixels farther than a 16-bit PNG holds (65.535 output units), clamped so far: reported once per run.</summary>
        public int ClampedDepthPixels => Volatile.Read(ref _clampedDepthPixels);

        /// <summary>
        /// Writes <paramref name="view"/>'s files. <paramref name="colour"/> carries colour (the black/white pair for
        /// <see cref="DifferenceMatting"/>, or one render whose alpha is the mask) and mask at the supersampled size; <paramref name="data"/> carries depth and normals (normals already in the output world frame), at
        /// that size or at the output size (supersampling 1). Either may be the same frame.
        /// </summary>
        public void Write(PlannedView view, RawFrame colour, RawFrame data)
        {
            int width = colour.OutputWidth, height = colour.OutputHeight;
            var wantsMask = view.Writes(DatasetFileKind.MaskPng);
            var rgba = new byte[width * height * 4];
            var mask = wantsMask ? new byte[width * height] : null;
            if (colour.ColorOverBlack != null)
            {
                // Alpha from the two colour renders; the mask file is the mask pass's geometry coverage (pixels.md §3).
                DifferenceMatting.Resolve(colour, rgba, _background);
                if (wantsMask) MaskEncoding.Encode(colour, mask);
            }
            else StraightAlpha.Resolve(colour, rgba, _background, mask);
            Save(view, DatasetFileKind.Color, PngWriter.Encode(rgba, width, height, PngPixelFormat.Rgba8));
            if (wantsMask) Save(view, DatasetFileKind.MaskPng, PngWriter.Encode(mask, width, height, PngPixelFormat.Gray8));

            if (view.Writes(DatasetFileKind.DepthPng))
            {
                var millimetres = new ushort[width * height];
                Interlocked.Add(ref _clampedDepthPixels, DepthEncoding.ToMillimetres(data, millimetres, _depthScale));
                Save(view, DatasetFileKind.DepthPng, PngWriter.EncodeGray16(millimetres, width, height));
            }
            if (view.Writes(DatasetFileKind.DepthExr))
            {
                var metres = new float[width * height];
                DepthEncoding.ToMetres(data, metres, RowDirection.BottomRowFirst, _depthScale);
                Save(view, DatasetFileKind.DepthExr, Exr(metres, width, height, 1));
            }
            if (view.Writes(DatasetFileKind.NormalPng))
            {
                var rgb = new byte[width * height * 3];
                NormalEncoding.Encode(data, rgb);
                Save(view, DatasetFileKind.NormalPng, PngWriter.Encode(rgb, width, height, PngPixelFormat.Rgb8));
            }
            if (view.Writes(DatasetFileKind.NormalExr))
            {
                var normals = new float[width * height * 4];
                NormalEncoding.ToFloats(data, normals, RowDirection.BottomRowFirst);
                Save(view, DatasetFileKind.NormalExr, Exr(normals, width, height, 4));
            }
        }

        byte[] Exr(float[] pixels, int width, int height, int channels)
        {
            if (_encodeExr == null)
                throw new InvalidOperationException("This run writes EXR files but no EXR encoder was given.");
            return _encodeExr(pixels, width, height, channels);
        }

        void Save(PlannedView view, DatasetFileKind kind, byte[] bytes)
        {
            var path = _session.PathOf(DatasetLayout.RelativePath(view.Split, view.Index, kind));
            Directory.CreateDirectory(Path.GetDirectoryName(path));
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
