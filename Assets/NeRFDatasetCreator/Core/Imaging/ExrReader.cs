using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>A decoded OpenEXR image: each channel's values as floats, rows top first (increasing y).</summary>
    public sealed class ExrImage
    {
        public ExrImage(int width, int height, IReadOnlyDictionary<string, float[]> channels)
        {
            Width = width;
            Height = height;
            Channels = channels;
        }

        public int Width { get; }
        public int Height { get; }

        /// <summary>By channel name (R, G, B, A, Y, …).</summary>
        public IReadOnlyDictionary<string, float[]> Channels { get; }

        public float[] Channel(string name) => Channels.TryGetValue(name, out var values) ? values : null;
    }

    /// <summary>
    /// Reads the EXR files this plugin writes (the check's HDR comparison): single-part scan-line images with HALF,
    /// FLOAT or UINT channels, uncompressed or ZIP/ZIPS (zlib of the byte-interleaved, delta-predicted block: OpenEXR
    /// "OpenEXR File Layout", and ImfZip.cpp) — <see cref="ExrWriter"/>'s output and Unity's
    /// <c>ImageConversion.EncodeArrayToEXR</c> with <c>CompressZIP</c>. Other compressions, tiles, multi-part files and
    /// subsampled channels are refused with an <see cref="InvalidDataException"/> naming the file.
    /// </summary>
    public static class ExrReader
    {
        public static ExrImage Read(string path) => Decode(File.ReadAllBytes(path), Path.GetFileName(path));

        public static ExrImage Decode(byte[] bytes, string name)
        {
            try { return DecodeUnchecked(bytes, name); }
            catch (Exception e) when (e is EndOfStreamException || e is ArgumentException || e is IndexOutOfRangeException || e is OverflowException)
            {
                throw new InvalidDataException(name + " is not a readable EXR file (" + e.Message + ").", e);
            }
        }

        static ExrImage DecodeUnchecked(byte[] bytes, string name)
        {
            var r = new BinaryReader(new MemoryStream(bytes, false), Encoding.ASCII);
            if (bytes.Length < 8 || r.ReadInt32() != 20000630) throw new InvalidDataException(name + " is not an EXR file (no magic number).");
            var version = r.ReadInt32();
            if ((version & 0xFF) != 2 || (version & 0x1A00) != 0)
                throw new InvalidDataException(name + " is a tiled, deep or multi-part EXR file; only single-part scan-line images are read.");
            var channels = new List<(string Name, int Type)>();
            int compression = -1, xMin = 0, yMin = 0, xMax = -1, yMax = -1, lineOrder = 0;
            while (true)
            {
                var attribute = Text(r);
                if (attribute.Length == 0) break;
                var type = Text(r);
                var size = r.ReadInt32();
                var end = r.BaseStream.Position + size;
                switch (attribute)
                {
                    case "channels":
                        while (true)
                        {
                            var channel = Text(r);
                            if (channel.Length == 0) break;
                            var pixelType = r.ReadInt32();
                            r.ReadInt32(); // pLinear, reserved
                            if (r.ReadInt32() != 1 || r.ReadInt32() != 1) throw new InvalidDataException(name + " has a subsampled channel " + channel + ".");
                            channels.Add((channel, pixelType));
                        }
                        break;
                    case "compression": compression = r.ReadByte(); break;
                    case "dataWindow": xMin = r.ReadInt32(); yMin = r.ReadInt32(); xMax = r.ReadInt32(); yMax = r.ReadInt32(); break;
                    case "lineOrder": lineOrder = r.ReadByte(); break;
                }
                r.BaseStream.Position = end;
            }
            int width = xMax - xMin + 1, height = yMax - yMin + 1;
            if (width < 1 || height < 1 || (long)width * height > 1L << 28) throw new InvalidDataException(name + " has a data window of " + width + "×" + height + ".");
            if (channels.Count == 0) throw new InvalidDataException(name + " has no channels.");
            int lines;
            switch (compression)
            {
                case 0: case 2: lines = 1; break; // NONE, ZIPS
                case 3: lines = 16; break;        // ZIP
                default: throw new InvalidDataException(name + " uses EXR compression " + compression + "; only none and ZIP are read.");
            }
            if (lineOrder == 2) throw new InvalidDataException(name + " has random line order.");
            var sizes = new int[channels.Count];
            var lineBytes = 0;
            for (var c = 0; c < channels.Count; c++)
            {
                sizes[c] = channels[c].Type == 1 ? 2 : channels[c].Type == 2 || channels[c].Type == 0 ? 4 : throw new InvalidDataException(name + " has channel " + channels[c].Name + " of unknown type " + channels[c].Type + ".");
                lineBytes += sizes[c] * width;
            }
            var values = new float[channels.Count][];
            for (var c = 0; c < channels.Count; c++) values[c] = new float[width * height];
            var chunks = (height + lines - 1) / lines;
            var offsets = new long[chunks];
            for (var i = 0; i < chunks; i++) offsets[i] = r.ReadInt64();
            foreach (var offset in offsets)
            {
                r.BaseStream.Position = offset;
                var y = r.ReadInt32() - yMin;
                var size = r.ReadInt32();
                var count = Math.Min(lines, height - y);
                if (y < 0 || count < 1) throw new InvalidDataException(name + " has a block at y " + (y + yMin) + " outside its data window.");
                var raw = count * lineBytes;
                var data = r.ReadBytes(size);
                if (data.Length != size) throw new EndOfStreamException("a block is cut short");
                if (compression != 0 && size < raw) data = Unzip(data, raw);
                if (data.Length != raw) throw new InvalidDataException(name + " has a block of " + data.Length + " bytes where " + raw + " were expected.");
                var at = 0;
                for (var line = 0; line < count; line++)
                    for (var c = 0; c < channels.Count; c++)
                    {
                        var row = (y + line) * width;
                        for (var x = 0; x < width; x++, at += sizes[c])
                            values[c][row + x] = channels[c].Type == 1 ? HalfFloat.ToFloat(BitConverter.ToUInt16(data, at))
                                : channels[c].Type == 2 ? BitConverter.ToSingle(data, at) : BitConverter.ToUInt32(data, at);
                    }
            }
            var byName = new Dictionary<string, float[]>();
            for (var c = 0; c < channels.Count; c++) byName[channels[c].Name] = values[c];
            return new ExrImage(width, height, byName);
        }

        /// <summary>zlib → predictor (each byte the previous plus it, minus 128) → de-interleave (first half the even bytes).</summary>
        static byte[] Unzip(byte[] data, int raw)
        {
            var t = new byte[raw];
            using (var inflate = new DeflateStream(new MemoryStream(data, 2, data.Length - 2), CompressionMode.Decompress))
            {
                var read = 0;
                while (read < raw)
                {
                    var n = inflate.Read(t, read, raw - read);
                    if (n == 0) break;
                    read += n;
                }
                if (read != raw) throw new InvalidDataException("a ZIP block inflates to " + read + " bytes, not " + raw + ".");
            }
            for (var i = 1; i < raw; i++) t[i] = (byte)(t[i - 1] + t[i] - 128);
            var output = new byte[raw];
            int half = (raw + 1) / 2;
            for (var i = 0; i < raw; i++) output[i] = (i & 1) == 0 ? t[i / 2] : t[half + i / 2];
            return output;
        }

        static string Text(BinaryReader r)
        {
            var sb = new StringBuilder();
            for (var i = 0; i < 256; i++)
            {
                var b = r.ReadByte();
                if (b == 0) return sb.ToString();
                sb.Append((char)b);
            }
            throw new InvalidDataException("a header name longer than 255 bytes");
        }
    }
}
