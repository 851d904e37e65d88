using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// JPEG for the layouts whose loaders read only JPEG (the Replica layout's <c>frame*.jpg</c>), through the codec the
    /// host installed (<see cref="IJpegCodec"/>): the tool and the .NET tests use LibJpeg.NET (a pure C# port of the IJG
    /// libjpeg whose quality scale the readers' libjpeg decoders share) with no chroma subsampling; Unity's Editor uses
    /// its own encoder. Checks the arguments here, so every codec gets the same refusals.
    /// </summary>
    public static class JpegWriter
    {
        /// <summary>
        /// The quality the exports write at: IJG quality 95 with 4:4:4 gives 43.0 dB PSNR at worst (44.1 dB mean) against
        /// the source on a 320 × 240 capture of the demo look, as SplaTAM's imageio decodes it
        /// (Documentation~/maintainers/layouts-slam.md, "Colour, and the JPEG encoder").
        /// </summary>
        public const int Quality = 95;

        static volatile IJpegCodec _codec;

        /// <summary>The codec in use; null until the host installs one (the tool's Program, Unity's Editor on load, the test setup).</summary>
        public static IJpegCodec Codec
        {
            get => _codec;
            set => _codec = value;
        }

        /// <summary>Encodes <paramref name="rgb"/> (R G B per pixel, top row first) at <paramref name="quality"/> (1–100).</summary>
        public static byte[] EncodeRgb(byte[] rgb, int width, int height, int quality = Quality)
        {
            if (width <= 0 || height <= 0 || width > 65500 || height > 65500)
                throw new ArgumentOutOfRangeException(nameof(width), width + " × " + height, "JPEG holds 1 to 65500 pixels a side.");
            if (rgb == null || rgb.Length != (long)width * height * 3) throw new ArgumentException("rgb must hold 3 bytes per pixel.", nameof(rgb));
            if (quality < 1 || quality > 100) throw new ArgumentOutOfRangeException(nameof(quality), quality, "JPEG quality is 1 to 100.");
            return Installed().Encode(rgb, width, height, quality);
        }

        /// <summary>Decodes a JPEG to 8-bit RGB (top row first) with the installed codec: for checks and tests.</summary>
        public static byte[] DecodeRgb(byte[] jpeg, out int width, out int height)
        {
            if (jpeg == null) throw new ArgumentNullException(nameof(jpeg));
            return Installed().Decode(jpeg, out width, out height);
        }

        static IJpegCodec Installed() => _codec ?? throw new InvalidOperationException(
            "No JPEG encoder is installed: the nerf-dataset tool installs LibJpeg.NET and Unity's Editor its own when they start. Code that calls Core directly sets JpegWriter.Codec first.");
    }
}
