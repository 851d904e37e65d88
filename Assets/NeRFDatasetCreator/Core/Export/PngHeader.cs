using System.Globalization;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The IHDR fields of a PNG (PNG spec §11.2.2: an 8-byte signature, then the IHDR chunk: length 13, type
    /// "IHDR", width and height as big-endian uint32, bit depth, colour type, …), read without decoding pixels.
    /// </summary>
    public sealed class PngHeader
    {
        PngHeader(int width, int height, int bitDepth, int colorType)
        {
            Width = width;
            Height = height;
            BitDepth = bitDepth;
            ColorType = colorType;
        }

        public int Width { get; }
        public int Height { get; }
        public int BitDepth { get; }

        /// <summary>0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA.</summary>
        public int ColorType { get; }

        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        public static PngHeader Read(string path)
        {
            var bytes = new byte[8 + 8 + 13];
            int read;
            using (var file = File.OpenRead(path))
            {
                read = 0;
                while (read < bytes.Length)
                {
                    var n = file.Read(bytes, read, bytes.Length - read);
                    if (n == 0) break;
                    read += n;
                }
            }
            var ok = read == bytes.Length;
            for (var i = 0; ok && i < 8; i++) ok = bytes[i] == Signature[i];
            ok = ok && BigEndian(bytes, 8) == 13 && bytes[12] == 'I' && bytes[13] == 'H' && bytes[14] == 'D' && bytes[15] == 'R';
            var width = ok ? BigEndian(bytes, 16) : 0;
            var height = ok ? BigEndian(bytes, 20) : 0;
            if (!ok || width <= 0 || height <= 0)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("file_path", path, "is not a PNG file (no PNG signature followed by an IHDR chunk).", "Point file_path at the PNG images of the dataset."),
                });
            return new PngHeader((int)width, (int)height, bytes[24], bytes[25]);
        }

        static long BigEndian(byte[] b, int offset) =>
            ((long)b[offset] << 24) | ((long)b[offset + 1] << 16) | ((long)b[offset + 2] << 8) | b[offset + 3];

        public override string ToString() => string.Format(CultureInfo.InvariantCulture, "{0}×{1}, {2}-bit, colour type {3}", Width, Height, BitDepth, ColorType);
    }
}
