using System;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A plain OpenEXR writer (scan-line, uncompressed, 32-bit float channels; OpenEXR "Technical Introduction" and
    /// "OpenEXR File Layout"): Core's own <see cref="ExrEncoder"/> for runs without Unity (analytic datasets, the demo),
    /// where the Unity layer passes ImageConversion.EncodeArrayToEXR. Rows arrive bottom-up (texture order) as the
    /// delegate says, and are written top row first (increasing y), as Unity's files are. 1 channel is written as Y,
    /// 3 as R G B (the relighting environments, lights/&lt;name&gt;.exr), 4 as R G B A (stored in the header's alphabetical order A B G R).
    /// </summary>
    public static class ExrWriter
    {
        public static byte[] Encode(float[] pixels, int width, int height, int channels)
        {
            if (channels != 1 && channels != 3 && channels != 4) throw new ArgumentOutOfRangeException(nameof(channels), channels, "1 (Y), 3 (RGB) or 4 (RGBA) channels are written.");
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), width + "×" + height, "An image has at least one pixel.");
            if (pixels == null || pixels.LongLength < (long)width * height * channels) throw new ArgumentException("Fewer than " + channels + " floats per pixel.", nameof(pixels));
            // Stored channel order (alphabetical) and each one's offset in an input pixel.
            var names = channels == 1 ? new[] { "Y" } : channels == 3 ? new[] { "B", "G", "R" } : new[] { "A", "B", "G", "R" };
            var offsets = channels == 1 ? new[] { 0 } : channels == 3 ? new[] { 2, 1, 0 } : new[] { 3, 2, 1, 0 };
            using (var stream = new MemoryStream())
            using (var w = new BinaryWriter(stream, Encoding.ASCII))
            {
                w.Write(20000630); // magic 76 2f 31 01
                w.Write(2);        // version 2, single-part scan-line, short names
                var channelList = new MemoryStream();
                using (var c = new BinaryWriter(channelList, Encoding.ASCII, true))
                {
                    foreach (var name in names)
                    {
                        c.Write(Encoding.ASCII.GetBytes(name)); c.Write((byte)0);
                        c.Write(2); // FLOAT
                        c.Write(0); // pLinear + 3 reserved bytes
                        c.Write(1); c.Write(1); // x and y sampling
                    }
                    c.Write((byte)0);
                }
                Attribute(w, "channels", "chlist", channelList.ToArray());
                Attribute(w, "compression", "compression", new byte[] { 0 });
                var box = Box(width, height);
                Attribute(w, "dataWindow", "box2i", box);
                Attribute(w, "displayWindow", "box2i", box);
                Attribute(w, "lineOrder", "lineOrder", new byte[] { 0 });
                Attribute(w, "pixelAspectRatio", "float", BitConverter.GetBytes(1f));
                Attribute(w, "screenWindowCenter", "v2f", new byte[8]);
                Attribute(w, "screenWindowWidth", "float", BitConverter.GetBytes(1f));
                w.Write((byte)0);
                int lineBytes = width * channels * 4, chunk = 8 + lineBytes;
                long first = stream.Position + 8L * height;
                for (var y = 0; y < height; y++) w.Write(first + (long)y * chunk);
                for (var y = 0; y < height; y++)
                {
                    w.Write(y);
                    w.Write(lineBytes);
                    var row = (long)(height - 1 - y) * width * channels;
                    for (var k = 0; k < names.Length; k++)
                        for (var x = 0; x < width; x++)
                            w.Write(pixels[row + (long)x * channels + offsets[k]]);
                }
                w.Flush();
                return stream.ToArray();
            }
        }

        static byte[] Box(int width, int height)
        {
            var box = new byte[16];
            BitConverter.GetBytes(width - 1).CopyTo(box, 8);
            BitConverter.GetBytes(height - 1).CopyTo(box, 12);
            return box;
        }

        static void Attribute(BinaryWriter w, string name, string type, byte[] value)
        {
            w.Write(Encoding.ASCII.GetBytes(name)); w.Write((byte)0);
            w.Write(Encoding.ASCII.GetBytes(type)); w.Write((byte)0);
            w.Write(value.Length);
            w.Write(value);
        }
    }
}
