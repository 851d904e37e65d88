using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What a PNG's header says (PNG spec §11.2.2 IHDR): size, bit depth and colour type, and whether the file's
    /// chunk structure runs complete to IEND. Reads the 8-byte signature, the IHDR chunk, then only the chunk
    /// lengths and types (seeking over data), so it is cheap even for large images; no pixel is decoded.
    /// </summary>
    public sealed class PngInfo
    {
        public const int ColorTypeGray = 0;
        public const int ColorTypeRgb = 2;
        public const int ColorTypePalette = 3;
        public const int ColorTypeGrayAlpha = 4;
        public const int ColorTypeRgba = 6;

        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        PngInfo(int width, int height, int bitDepth, int colorType)
        {
            Width = width;
            Height = height;
            BitDepth = bitDepth;
            ColorType = colorType;
        }

        public int Width { get; }
        public int Height { get; }
        public int BitDepth { get; }
        public int ColorType { get; }

        public int Channels
        {
            get
            {
                switch (ColorType)
                {
                    case ColorTypeGray: return 1;
                    case ColorTypeRgb: return 3;
                    case ColorTypePalette: return 1;
                    case ColorTypeGrayAlpha: return 2;
                    case ColorTypeRgba: return 4;
                    default: return 0;
                }
            }
        }

        /// <summary>E.g. "8-bit RGBA", "16-bit grey".</summary>
        public string Describe() => BitDepth + "-bit " + ColorTypeName(ColorType);

        public static string ColorTypeName(int colorType)
        {
            switch (colorType)
            {
                case ColorTypeGray: return "grey";
                case ColorTypeRgb: return "RGB";
                case ColorTypePalette: return "palette";
                case ColorTypeGrayAlpha: return "grey+alpha";
                case ColorTypeRgba: return "RGBA";
                default: return "colour type " + colorType;
            }
        }

        /// <summary>Reads a PNG file's header and checks its chunk structure; throws <see cref="InvalidDataException"/> saying what is wrong.</summary>
        public static PngInfo Read(string path)
        {
            ReadableFile.Length(path, long.MaxValue); // a pipe or device is refused unopened (opening a FIFO waits forever)
            using (var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, 4096, FileOptions.SequentialScan))
                return Read(stream);
        }

        public static PngInfo Read(Stream stream)
        {
            var signature = new byte[8];
            if (ReadFully(stream, signature) < 8 || !Same(signature, Signature))
                throw new InvalidDataException("is not a PNG file (its first 8 bytes are not the PNG signature).");
            var header = new byte[8];
            if (ReadFully(stream, header) < 8) throw new InvalidDataException("is truncated: it ends inside the IHDR chunk header.");
            var length = BigEndian(header, 0);
            if (header[4] != 'I' || header[5] != 'H' || header[6] != 'D' || header[7] != 'R' || length != 13)
                throw new InvalidDataException("does not start with a 13-byte IHDR chunk as the PNG spec requires.");
            var ihdr = new byte[13 + 4];
            if (ReadFully(stream, ihdr) < ihdr.Length) throw new InvalidDataException("is truncated: it ends inside the IHDR chunk.");
            var width = BigEndian(ihdr, 0);
            var height = BigEndian(ihdr, 4);
            if (width <= 0 || height <= 0) throw new InvalidDataException("declares an empty or impossible size " + width + "×" + height + ".");
            var info = new PngInfo(width, height, ihdr[8], ihdr[9]);

            var sawData = false;
            while (true)
            {
                var chunk = new byte[8];
                var got = ReadFully(stream, chunk);
                if (got == 0) throw new InvalidDataException("is truncated: it ends before the IEND chunk.");
                if (got < 8) throw new InvalidDataException("is truncated: it ends inside a chunk header.");
                long chunkLength = (uint)BigEndian(chunk, 0);
                var type = "" + (char)chunk[4] + (char)chunk[5] + (char)chunk[6] + (char)chunk[7];
                if (chunkLength > int.MaxValue) throw new InvalidDataException("has a corrupt chunk length in chunk '" + type + "'.");
                if (type == "IDAT") sawData = true;
                if (!Skip(stream, chunkLength + 4)) throw new InvalidDataException("is truncated: it ends inside the '" + type + "' chunk.");
                if (type == "IEND")
                {
                    if (!sawData) throw new InvalidDataException("has no image data (IDAT chunk).");
                    return info;
                }
            }
        }

        static bool Skip(Stream stream, long count)
        {
            if (stream.CanSeek)
            {
                if (stream.Position + count > stream.Length) return false;
                stream.Seek(count, SeekOrigin.Current);
                return true;
            }
            var buffer = new byte[8192];
            while (count > 0)
            {
                var n = stream.Read(buffer, 0, (int)Math.Min(buffer.Length, count));
                if (n <= 0) return false;
                count -= n;
            }
            return true;
        }

        static int ReadFully(Stream stream, byte[] buffer)
        {
            var total = 0;
            while (total < buffer.Length)
            {
                var n = stream.Read(buffer, total, buffer.Length - total);
                if (n <= 0) break;
                total += n;
            }
            return total;
        }

        static int BigEndian(byte[] b, int offset) => (b[offset] << 24) | (b[offset + 1] << 16) | (b[offset + 2] << 8) | b[offset + 3];

        static bool Same(byte[] a, byte[] b)
        {
            for (var i = 0; i < b.Length; i++)
                if (a[i] != b[i]) return false;
            return true;
        }
    }
}
