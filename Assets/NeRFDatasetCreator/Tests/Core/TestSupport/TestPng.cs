using System;
using System.IO;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Blank (all-zero) PNG files of a given size and format for dataset fixtures, encoded by Core's PngWriter, whose
    /// output the Imaging tests check bit-exactly against a decoder written from the PNG specification.
    /// </summary>
    static class TestPng
    {
        public static byte[] Encode(int width, int height, int bitDepth, int colorType)
        {
            var format = FormatOf(bitDepth, colorType);
            return format == PngPixelFormat.Gray16
                ? PngWriter.EncodeGray16(new ushort[width * height], width, height)
                : PngWriter.Encode(new byte[width * height * PngWriter.BytesPerPixel(format)], width, height, format);
        }

        public static void Write(string path, int width, int height, int bitDepth = 8, int colorType = PngInfo.ColorTypeRgba)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(path)));
            File.WriteAllBytes(path, Encode(width, height, bitDepth, colorType));
        }

        static PngPixelFormat FormatOf(int bitDepth, int colorType)
        {
            if (bitDepth == 16 && colorType == PngInfo.ColorTypeGray) return PngPixelFormat.Gray16;
            if (bitDepth == 8 && colorType == PngInfo.ColorTypeGray) return PngPixelFormat.Gray8;
            if (bitDepth == 8 && colorType == PngInfo.ColorTypeRgb) return PngPixelFormat.Rgb8;
            if (bitDepth == 8 && colorType == PngInfo.ColorTypeRgba) return PngPixelFormat.Rgba8;
            throw new ArgumentException("TestPng makes only the formats PngWriter writes, not " + bitDepth + "-bit colour type " + colorType + ".");
        }
    }
}
