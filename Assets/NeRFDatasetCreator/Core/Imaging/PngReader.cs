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

        /// <summary>The largest side of an image this reader decodes at full area: the plugin's largest capture (<see cref="DatasetSettings.MaxSize"/>).</summary>
        public const int MaxSide = DatasetSettings.MaxSize;

        /// <summary>The most pixels decoded: <see cref="MaxSide"/>² (any aspect ratio).</summary>
        public const long MaxPixels = (long)MaxSide * MaxSide;

        /// <summary>The largest factor by which deflate data can expand (zlib FAQ: 1032:1).</summary>
        const long MaxDeflateRatio = 1032;

        /// <summary>Reads and decodes the file; a file that cannot be read is an <see cref="IOException"/> naming it.</summary>
        public static PngImage Read(string path)
        {
            byte[] bytes;
            try { bytes = ReadableFile.ReadAllBytes(path, ReadableFile.MaxImageBytes); }
            catch (IOException e) when (e.Message.IndexOf(path, StringComparison.Ordinal) < 0) { throw new IOException(path + ": " + e.Message, e); }
            return Decode(bytes, path);
        }

        /// <summary>Decodes <paramref name="bytes"/>; <paramref name="name"/> names the file in errors.</summary>
        public static PngImage Decode(byte[] bytes, string name)
        {
            for (var i = 0; i < Signature.Length; i++)
                if (bytes.Length < Signature.Length || bytes[i] != Signature[i]) throw Bad(name, "is not a PNG file.");
            int width = 0, height = 0, depth = 0, colorType = -1;
            var idat = new PngIdatStream(bytes);
            var pos = 8;
            while (pos + 8 <= bytes.Length)
            {
                var length = BigEndian(bytes, pos);
                var data = pos + 8;
                if (length < 0 || data + (long)length + 4 > bytes.Length) throw Bad(name, "is truncated.");
                if (Is(bytes, pos + 4, 'I', 'H', 'D', 'R'))
                {
                    width = BigEndian(bytes, data);
                    height = BigEndian(bytes, data + 4);
                    depth = bytes[data + 8];
                    colorType = bytes[data + 9];
                    if ((depth != 8 && depth != 16) || ChannelsOf(colorType) == 0 || bytes[data + 12] != 0)
                        throw Bad(name, "is a " + depth + "-bit PNG of colour type " + colorType + (bytes[data + 12] != 0 ? ", interlaced" : "") +
                                        "; only 8- and 16-bit grey, grey + alpha, RGB and RGBA without interlacing are read.");
                }
                else if (Is(bytes, pos + 4, 'I', 'D', 'A', 'T')) idat.Add(data, length);
                else if (Is(bytes, pos + 4, 'I', 'E', 'N', 'D')) break;
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
            // A 1.5 MB PNG of zeros can claim 20000×20000 pixels (1.6 GB decoded, within deflate's 1032:1): nothing this
            // plugin writes or reads is larger than its largest capture, so a bigger claim is refused before allocating.
            if ((long)width * height > MaxPixels)
                throw Bad(name, "claims " + width + "×" + height + " pixels, more than the " + MaxSide + "×" + MaxSide + " this tool decodes (the largest capture it makes).");
            idat.Position = 2; // zlib header (RFC 1950); DeflateStream reads the raw deflate data after it
            var pixels = new byte[stride * height];
            using (var inflater = new DeflateStream(idat, CompressionMode.Decompress))
                Inflate(inflater, pixels, (int)stride, height, bytesPerPixel, name);
            return new PngImage(width, height, depth, colorType, pixels);
        }

        /// <summary>
        /// Inflates the filtered rows a band at a time straight into a scratch buffer and undoes each row's filter into
        /// <paramref name="pixels"/> (PNG spec §9.2), one loop per filter type: no per-byte switch, no copy of the whole
        /// filtered image.
        /// </summary>
        static void Inflate(Stream inflater, byte[] pixels, int stride, int height, int bpp, string name)
        {
            var rowBytes = stride + 1;
            var band = Math.Max(1, Math.Min(height, (1 << 18) / rowBytes));
            // The thread's scratch rows, kept between calls: a 256 KiB array per decode would be a large-object allocation.
            var raw = Scratch(ref bandScratch, band * rowBytes);
            var zero = Scratch(ref zeroScratch, stride);
            Array.Clear(zero, 0, stride);
            for (var y0 = 0; y0 < height; y0 += band)
            {
                var rows = Math.Min(band, height - y0);
                var want = rows * rowBytes;
                var read = 0;
                while (read < want)
                {
                    var n = inflater.Read(raw, read, want - read);
                    if (n == 0) throw Bad(name, "has less image data than its size needs.");
                    read += n;
                }
                for (var r = 0; r < rows; r++)
                {
                    var y = y0 + r;
                    var src = r * rowBytes + 1;
                    var dst = y * stride;
                    // The row above, or zeros for the first row (the spec's value for bytes outside the image).
                    var up = y > 0 ? pixels : zero;
                    var upAt = y > 0 ? dst - stride : 0;
                    switch (raw[src - 1])
                    {
                        case 0: Buffer.BlockCopy(raw, src, pixels, dst, stride); break;
                        case 1: PngUnfilter.Sub(raw, src, pixels, dst, stride, bpp); break;
                        case 2: PngUnfilter.Up(raw, src, pixels, dst, up, upAt, stride); break;
                        case 3: PngUnfilter.Average(raw, src, pixels, dst, up, upAt, stride, bpp); break;
                        case 4: PngUnfilter.Paeth(raw, src, pixels, dst, up, upAt, stride, bpp); break;
                        default: throw Bad(name, "has an unknown row filter " + raw[src - 1] + " on row " + y + ".");
                    }
                }
            }
        }

        [ThreadStatic] static byte[] bandScratch, zeroScratch;

        static byte[] Scratch(ref byte[] array, int length)
        {
            if (array == null || array.Length < length) array = new byte[length];
            return array;
        }

        static bool Is(byte[] b, int i, char c0, char c1, char c2, char c3) => b[i] == c0 && b[i + 1] == c1 && b[i + 2] == c2 && b[i + 3] == c3;

        static int BigEndian(byte[] b, int i) => (b[i] << 24) | (b[i + 1] << 16) | (b[i + 2] << 8) | b[i + 3];

        static InvalidDataException Bad(string name, string reason) => new InvalidDataException(name + " " + reason);
    }
}
