using System;
using System.IO;
using BitMiracle.LibJpeg.Classic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Baseline JPEG (JFIF) of 8-bit RGB through LibJpeg.NET (BitMiracle, BSD-3-Clause; Plugins/LibJpeg.NET), a pure C#
    /// port of the IJG libjpeg whose quality scale the readers' libjpeg decoders share. Used where a loader reads only
    /// JPEG (the Replica layout's <c>frame*.jpg</c>). No chroma subsampling (4:4:4, every component 1×1): colour edges
    /// stay sharp, which is what a reconstruction is scored on. Deterministic: the same pixels give the same bytes.
    /// </summary>
    public static class JpegWriter
    {
        /// <summary>
        /// The quality the exports write at: IJG quality 95 with 4:4:4 gives 43.0 dB PSNR at worst (44.1 dB mean) against
        /// the source on a 320 × 240 capture of the demo look, as SplaTAM's imageio decodes it
        /// (Documentation~/maintainers/layouts-slam.md, "Colour, and the JPEG encoder").
        /// </summary>
        public const int Quality = 95;

        /// <summary>Encodes <paramref name="rgb"/> (R G B per pixel, top row first) at <paramref name="quality"/> (1–100).</summary>
        public static byte[] EncodeRgb(byte[] rgb, int width, int height, int quality = Quality)
        {
            if (width <= 0 || height <= 0 || width > 65500 || height > 65500)
                throw new ArgumentOutOfRangeException(nameof(width), width + " × " + height, "JPEG holds 1 to 65500 pixels a side.");
            if (rgb == null || rgb.Length != (long)width * height * 3) throw new ArgumentException("rgb must hold 3 bytes per pixel.", nameof(rgb));
            if (quality < 1 || quality > 100) throw new ArgumentOutOfRangeException(nameof(quality), quality, "JPEG quality is 1 to 100.");
            using (var output = new MemoryStream())
            {
                var compressor = new jpeg_compress_struct(new jpeg_error_mgr());
                compressor.Image_width = width;
                compressor.Image_height = height;
                compressor.Input_components = 3;
                compressor.In_color_space = J_COLOR_SPACE.JCS_RGB;
                compressor.jpeg_set_defaults();
                compressor.jpeg_set_quality(quality, true);
                foreach (var component in compressor.Component_info)
                {
                    component.H_samp_factor = 1;
                    component.V_samp_factor = 1;
                }
                compressor.jpeg_stdio_dest(output);
                compressor.jpeg_start_compress(true);
                var row = new byte[1][];
                row[0] = new byte[width * 3];
                for (var y = 0; y < height; y++)
                {
                    Buffer.BlockCopy(rgb, y * width * 3, row[0], 0, width * 3);
                    compressor.jpeg_write_scanlines(row, 1);
                }
                compressor.jpeg_finish_compress();
                return output.ToArray();
            }
        }

        /// <summary>Decodes a JPEG to 8-bit RGB (top row first) with the same library: for checks and tests.</summary>
        public static byte[] DecodeRgb(byte[] jpeg, out int width, out int height)
        {
            using (var input = new MemoryStream(jpeg))
            {
                var decompressor = new jpeg_decompress_struct(new jpeg_error_mgr());
                decompressor.jpeg_stdio_src(input);
                decompressor.jpeg_read_header(true);
                decompressor.Out_color_space = J_COLOR_SPACE.JCS_RGB;
                decompressor.jpeg_start_decompress();
                width = decompressor.Output_width;
                height = decompressor.Output_height;
                var rgb = new byte[width * height * 3];
                var row = new byte[1][];
                row[0] = new byte[width * 3];
                for (var y = 0; y < height; y++)
                {
                    decompressor.jpeg_read_scanlines(row, 1);
                    Buffer.BlockCopy(row[0], 0, rgb, y * width * 3, width * 3);
                }
                decompressor.jpeg_finish_decompress();
                return rgb;
            }
        }
    }
}
