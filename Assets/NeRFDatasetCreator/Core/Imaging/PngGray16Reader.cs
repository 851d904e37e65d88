using System;
using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads the samples of a 16-bit greyscale, non-interlaced PNG — the depth files this plugin writes — for the
    /// exporters that re-encode depth (PNG spec §11.2.2 IHDR, §11.2.4 IDAT, §9 filters, §7.2 big-endian samples).
    /// Every other kind of PNG is refused with a message naming the file; a general decoder is out of scope.
    /// </summary>
    public static class PngGray16Reader
    {
        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        /// <summary>The samples, top row first.</summary>
        public static ushort[] Read(string path, out int width, out int height)
        {
            var bytes = File.ReadAllBytes(path);
            for (var i = 0; i < Signature.Length; i++)
                if (bytes.Length < Signature.Length || bytes[i] != Signature[i]) throw Bad(path, "is not a PNG file.");
            width = height = 0;
            var idat = new MemoryStream();
            var pos = 8;
            var sawHeader = false;
            while (pos + 8 <= bytes.Length)
            {
                var length = (bytes[pos] << 24) | (bytes[pos + 1] << 16) | (bytes[pos + 2] << 8) | bytes[pos + 3];
                var type = System.Text.Encoding.ASCII.GetString(bytes, pos + 4, 4);
                var data = pos + 8;
                if (length < 0 || data + length + 4 > bytes.Length) throw Bad(path, "is truncated.");
                if (type == "IHDR")
                {
                    width = BigEndian(bytes, data);
                    height = BigEndian(bytes, data + 4);
                    if (bytes[data + 8] != 16 || bytes[data + 9] != PngInfo.ColorTypeGray || bytes[data + 12] != 0)
                        throw Bad(path, "is not a 16-bit greyscale, non-interlaced PNG (the depth layout).");
                    sawHeader = true;
                }
                else if (type == "IDAT") idat.Write(bytes, data, length);
                else if (type == "IEND") break;
                pos = data + length + 4;
            }
            if (!sawHeader || width <= 0 || height <= 0) throw Bad(path, "has no usable IHDR chunk.");

            var stride = width * 2;
            var raw = new byte[(long)(stride + 1) * height];
            idat.Position = 2; // zlib header (RFC 1950); DeflateStream reads the raw deflate data after it
            using (var inflater = new DeflateStream(idat, CompressionMode.Decompress))
            {
                var read = 0;
                while (read < raw.Length)
                {
                    var n = inflater.Read(raw, read, raw.Length - read);
                    if (n == 0) throw Bad(path, "has less image data than its size needs.");
                    read += n;
                }
            }

            var samples = new ushort[width * height];
            var previous = new byte[stride];
            var row = new byte[stride];
            for (var y = 0; y < height; y++)
            {
                var start = y * (stride + 1);
                var filter = raw[start];
                for (var x = 0; x < stride; x++)
                {
                    int a = x >= 2 ? row[x - 2] : 0, b = previous[x], c = x >= 2 ? previous[x - 2] : 0;
                    int v = raw[start + 1 + x];
                    switch (filter)
                    {
                        case 0: break;
                        case 1: v += a; break;
                        case 2: v += b; break;
                        case 3: v += (a + b) >> 1; break;
                        case 4: v += Paeth(a, b, c); break;
                        default: throw Bad(path, "has an unknown row filter " + filter + ".");
                    }
                    row[x] = (byte)v;
                }
                for (var x = 0; x < width; x++) samples[y * width + x] = (ushort)((row[2 * x] << 8) | row[2 * x + 1]);
                var swap = previous; previous = row; row = swap;
            }
            return samples;
        }

        static int Paeth(int a, int b, int c)
        {
            var p = a + b - c;
            int pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
            return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }

        static int BigEndian(byte[] b, int i) => (b[i] << 24) | (b[i + 1] << 16) | (b[i + 2] << 8) | b[i + 3];

        static InvalidParameterException Bad(string path, string reason) =>
            new InvalidParameterException(new[] { new ValidationProblem("depth", path, reason, "Re-capture the depth with this plugin (16-bit PNG).") });
    }
}
