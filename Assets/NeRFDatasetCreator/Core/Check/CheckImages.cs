using System;
using System.Diagnostics;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One view's decoded planes, top row first, W×H each: alpha (null when the colour image has none), mask (8-bit
    /// coverage), depth (16-bit steps of <see cref="CheckView.DepthScale"/>, 0 = no surface) and normals (8-bit RGB,
    /// output world, (0, 0, 0) = background). A plane whose file is missing or of another format is null, and
    /// <see cref="Notes"/> says why.
    /// </summary>
    public sealed class CheckImages
    {
        public int Width, Height;
        public byte[] Alpha, Mask, Normals;

        /// <summary>Motion blur: the blurred image's alpha (<see cref="CheckView.BlurredFile"/>); <see cref="Alpha"/> is then the sharp image's.</summary>
        public byte[] BlurredAlpha;

        /// <summary>The decoded colour image (and the blurred one with motion blur), for the checks that read colour (<see cref="StraightAlphaCheck"/>).</summary>
        public PngImage ColourImage, BlurredImage;
        public ushort[] Depth;

        /// <summary>The 16-bit instance and semantic id maps (labels.md), 0 = background; null when the frame names none.</summary>
        public ushort[] Instance, Semantic;

        /// <summary>Why a file named by the frame was not used (wrong format or size, unreadable), one line each.</summary>
        public readonly System.Collections.Generic.List<DatasetProblem> Notes = new System.Collections.Generic.List<DatasetProblem>();

        /// <summary>Ticks spent reading and decoding.</summary>
        public long DecodeTicks;

        /// <summary>
        /// Decodes <paramref name="view"/>'s files. Returns null (and a note) when the colour image itself cannot be decoded.
        /// With <paramref name="depthOnly"/> only the depth and instance files are read (the multi-view pass).
        /// </summary>
        public static CheckImages Load(string root, CheckView view, bool depthOnly = false)
        {
            var images = new CheckImages();
            var started = Stopwatch.GetTimestamp();
            try
            {
                if (!depthOnly)
                {
                    var colour = Decode(root, view.ColourFile, view, "colour", images);
                    if (colour == null) return images;
                    images.Width = colour.Width;
                    images.Height = colour.Height;
                    images.ColourImage = colour;
                    if (colour.BitDepth == 8 && (colour.Channels == 4 || colour.Channels == 2)) images.Alpha = Channel(colour, colour.Channels - 1);
                    else if (colour.BitDepth == 16 && (colour.Channels == 4 || colour.Channels == 2)) images.Alpha = HighBytes(colour, colour.Channels - 1);
                    images.Mask = Plane(root, view.MaskFile, view, images, 8, 1, "mask", "8-bit grey")?.Samples;
                    var blurred = Plane(root, view.BlurredFile, view, images, 8, 4, "blurred colour", "8-bit RGBA");
                    if (blurred != null) images.BlurredAlpha = Channel(blurred, 3);
                    images.BlurredImage = blurred;
                    images.Normals = Plane(root, view.NormalFile, view, images, 8, 3, "normal", "8-bit RGB")?.Samples;
                    var semantic = Plane(root, view.SemanticFile, view, images, 16, 1, "semantic", "16-bit grey");
                    if (semantic != null) images.Semantic = Gray16(semantic.Samples);
                }
                else if (view.Camera != null)
                {
                    images.Width = view.Camera.Width;
                    images.Height = view.Camera.Height;
                }
                var depth = Plane(root, view.DepthFile, view, images, 16, 1, "depth", "16-bit grey");
                if (depth != null) images.Depth = Gray16(depth.Samples);
                // The multi-view pass reads the instance map too (InstanceReprojectionCheck).
                var instance = Plane(root, view.InstanceFile, view, images, 16, 1, "instance", "16-bit grey");
                if (instance != null) images.Instance = Gray16(instance.Samples);
            }
            finally
            {
                images.DecodeTicks = Stopwatch.GetTimestamp() - started;
            }
            return images;
        }

        public bool HasColour => Width > 0;

        static PngImage Plane(string root, string file, CheckView view, CheckImages images, int bitDepth, int channels, string what, string format)
        {
            if (file == null) return null;
            var png = Decode(root, file, view, what, images);
            if (png == null) return null;
            if (png.BitDepth != bitDepth || png.Channels != channels)
            {
                images.Notes.Add(new DatasetProblem(CheckDatasetReader.CheckName, "./" + file, view.Frame,
                    "is a " + png.BitDepth + "-bit PNG with " + png.Channels + " channel(s), not the " + format + " layout of a " + what + " file (output-format.md); it is not used."));
                return null;
            }
            if (images.Width > 0 && (png.Width != images.Width || png.Height != images.Height))
            {
                images.Notes.Add(new DatasetProblem(CheckDatasetReader.CheckName, "./" + file, view.Frame,
                    "is " + png.Width + "×" + png.Height + " but the colour image is " + images.Width + "×" + images.Height + "; it is not used."));
                return null;
            }
            return png;
        }

        static PngImage Decode(string root, string file, CheckView view, string what, CheckImages images)
        {
            try
            {
                return PngReader.Read(Path.Combine(root, file));
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
            {
                images.Notes.Add(new DatasetProblem(CheckDatasetReader.CheckName, "./" + file, view.Frame, "cannot be decoded as the " + what + " image: " + e.Message));
                return null;
            }
        }

        static byte[] Channel(PngImage png, int channel)
        {
            var n = png.Width * png.Height;
            var c = png.Channels;
            var s = png.Samples;
            var plane = new byte[n];
            for (int i = 0, j = channel; i < n; i++, j += c) plane[i] = s[j];
            return plane;
        }

        static byte[] HighBytes(PngImage png, int channel)
        {
            var n = png.Width * png.Height;
            var c = png.Channels * 2;
            var s = png.Samples;
            var plane = new byte[n];
            for (int i = 0, j = channel * 2; i < n; i++, j += c) plane[i] = s[j];
            return plane;
        }

        static ushort[] Gray16(byte[] bytes)
        {
            var samples = new ushort[bytes.Length / 2];
            for (int i = 0, j = 0; i < samples.Length; i++, j += 2) samples[i] = (ushort)((bytes[j] << 8) | bytes[j + 1]);
            return samples;
        }
    }
}
