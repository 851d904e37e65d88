using System;
using System.IO;
using BitMiracle.LibJpeg.Classic;

namespace NerfDatasetCreator.Tool
{
    /// <summary>
    /// JPEG through LibJpeg.NET (BitMiracle, BSD-3-Clause, NuGet <c>BitMiracle.LibJpeg.NET</c> 1.5.324), a pure C# port of
    /// the IJG libjpeg: baseline JFIF, no chroma subsampling (4:4:4, every component 1×1) so colour edges stay sharp,
    /// deterministic (the same pixels give the same bytes). The tool installs it (<see cref="Program.Run"/>); the .NET
    /// tests compile this file and install it too. Not part of the Unity package (Tools~ is not imported).
    /// </summary>
    public sealed class LibJpegCodec : IJpegCodec
    {
        public string Name => "LibJpeg.NET 1.5.324, 4:4:4";

        public byte[] Encode(byte[] rgb, int width, int height, int quality)
        {
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

        public byte[] Decode(byte[] jpeg, out int width, out int height)
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
