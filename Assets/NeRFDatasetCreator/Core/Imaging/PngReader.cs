using System;
using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator
{
    /// <summary>A decoded PNG: <see cref="Channels"/> samples per pixel, rows top first, 16-bit samples big-endian as stored.</summary>
    public sealed class PngImage
    {
        public PngImage(int width, int height, int bitDepth, int colorType, byte[] samples)
        {
            Width = width;
            Height = height;
            BitDepth = bitDepth;
            ColorType = colorType;
            Samples = samples;
        }

        public int Width { get; }
        public int Height { get; }
        public int BitDepth { get; }

        /// <summary>PNG colour type (<see cref="PngInfo.ColorTypeGray"/>, …).</summary>
        public int ColorType { get; }

        public byte[] Samples { get; }

        public int Channels => PngReader.ChannelsOf(ColorType);
    }

    /// <summary>
    /// Reads the PNGs this plugin writes — 8- or 16-bit greyscale, grey + alpha, RGB and RGBA, non-interlaced (PNG spec
    /// §11.2.2 IHDR, §11.2.4 IDAT, §9 filters, §7.2 big-endian samples) — for the exporters that re-encode pixels
    /// (depth for 3DGS, colour and masks for Dynamic 3D Gaussians). Palette images, other bit depths and interlacing
    /// are refused with an <see cref="InvalidDataException"/> naming the file. The tests check it against an
    /// independent decoder written from the specification (ReferencePngDecoder).
    /// </summary>
    public static class PngReader
    {
        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        public static int ChannelsOf(int colorType)
        {
            switch (colorType)
            {
                case PngInfo.ColorTypeGray: return 1;
                case PngInfo.ColorTypeGrayAlpha: return 2;
                case PngInfo.ColorTypeRgb: return 3;
                case PngInfo.ColorTypeRgba: return 4;
                default: return 0;
            }
        }

        /// <summary>The largest factor by which deflate data can expand (zlib FAQ: 1032:1).</summary>
        const long MaxDeflateRatio = 1032;

        /// <summary>Reads and decodes the file; a file that cannot be read is an <see cref="IOException"/> naming it.</summary>
        public static PngImage Read(string path)
        {
            byte[] bytes;
            try { bytes = File.ReadAllBytes(path); }
            catch (IOException e) when (e.Message.IndexOf(path, StringComparison.Ordinal) < 0) { throw new IOException(path + ": " + e.Message, e); }
            return Decode(bytes, path);
        }

        /// <summary>Decodes <paramref name="bytes"/>; <paramref name="name"/> names the file in errors.</summary>
        public static PngImage Decode(byte[] bytes, string name)
        {
            for (var i = 0; i < Signature.Length; i++)
                if (bytes.Length < Signature.Length || bytes[i] != Signature[i]) throw Bad(name, "is not a PNG file.");
            int width = 0, height = 0, depth = 0, colorType = -1;
            var idat = new MemoryStream();
            var pos = 8;
            while (pos + 8 <= bytes.Length)
            {
                var length = BigEndian(bytes, pos);
                var type = System.Text.Encoding.ASCII.GetString(bytes, pos + 4, 4);
                var data = pos + 8;
                if (length < 0 || data + (long)length + 4 > bytes.Length) throw Bad(name, "is truncated.");
                if (type == "IHDR")
                {
                    width = BigEndian(bytes, data);
                    height = BigEndian(bytes, data + 4);
                    depth = bytes[data + 8];
                    colorType = bytes[data + 9];
                    if ((depth != 8 && depth != 16) || ChannelsOf(colorType) == 0 || bytes[data + 12] != 0)
                        throw Bad(name, "is a " + depth + "-bit PNG of colour type " + colorType + (bytes[data + 12] != 0 ? ", interlaced" : "") +
                                        "; only 8- and 16-bit grey, grey + alpha, RGB and RGBA without interlacing are read.");
                }
                else if (type == "IDAT") idat.Write(bytes, data, length);
                else if (type == "IEND") break;
                pos = data + length + 4;
            }
            if (colorType < 0 || width <= 0 || height <= 0) throw Bad(name, "has no usable IHDR chunk.");

            var bytesPerPixel = ChannelsOf(colorType) * depth / 8;
            var stride = (long)width * bytesPerPixel;
            if (stride * height > int.MaxValue) throw Bad(name, "is too large to decode (" + width + "×" + height + ").");
            if (idat.Length < 2) throw Bad(name, "has no image data.");
            // Deflate expands at most 1032:1 (zlib's FAQ, "maximum compression factor"): a header claiming more pixels
            // than the file's image data can inflate to is refused before its buffer is allocated.
            if ((stride + 1) * height > MaxDeflateRatio * (idat.Length + 1))
                throw Bad(name, "claims " + width + "×" + height + " pixels, more than its " + idat.Length + " bytes of image data can hold (deflate expands at most " + MaxDeflateRatio + ":1); it is truncated or its header is wrong.");
            var raw = new byte[(stride + 1) * height];
            idat.Position = 2; // zlib header (RFC 1950); DeflateStream reads the raw deflate data after it
            using (var inflater = new DeflateStream(idat, CompressionMode.Decompress))
            {
                var read = 0;
                while (read < raw.Length)
                {
                    var n = inflater.Read(raw, read, raw.Length - read);
                    if (n == 0) throw Bad(name, "has less image data than its size needs.");
                    read += n;
                }
            }
            return new PngImage(width, height, depth, colorType, Unfilter(raw, (int)stride, height, bytesPerPixel, name));
        }

        /// <summary>PNG spec §9.2: undoes each row's filter in place of a copy without the filter bytes.</summary>
        static byte[] Unfilter(byte[] raw, int stride, int height, int bpp, string name)
        {
            var pixels = new byte[(long)stride * height];
            for (var y = 0; y < height; y++)
            {
                var src = y * (stride + 1);
                var dst = y * stride;
                var filter = raw[src];
                for (var x = 0; x < stride; x++)
                {
                    int a = x >= bpp ? pixels[dst + x - bpp] : 0;
                    int b = y > 0 ? pixels[dst - stride + x] : 0;
                    int c = x >= bpp && y > 0 ? pixels[dst - stride + x - bpp] : 0;
                    int v = raw[src + 1 + x];
                    switch (filter)
                    {
                        case 0: break;
                        case 1: v += a; break;
                        case 2: v += b; break;
                        case 3: v += (a + b) >> 1; break;
                        case 4: v += Paeth(a, b, c); break;
                        default: throw Bad(name, "has an unknown row filter " + filter + " on row " + y + ".");
                    }
                    pixels[dst + x] = (byte)v;
                }
            }
            return pixels;
        }

        static int Paeth(int a, int b, int c)
        {
            var p = a + b - c;
            int pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
            return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }

        static int BigEndian(byte[] b, int i) => (b[i] << 24) | (b[i + 1] << 16) | (b[i + 2] << 8) | b[i + 3];

        static InvalidDataException Bad(string name, string reason) => new InvalidDataException(name + " " + reason);
    }
}
