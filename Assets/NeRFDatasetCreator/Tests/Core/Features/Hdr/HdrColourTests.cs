using System;
using System.IO;
using System.IO.Compression;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The HDR view stage on hand-made RawFrame data, the settings, and the EXR writer and reader.</summary>
    public class HdrColourTests
    {
        static ushort H(double v) => HalfFloat.FromFloat((float)v);

        /// <summary>One sample: premultiplied colour p at coverage a, so over black K = p and over white W = p + (1 − a).</summary>
        static void Sample(RawFrame f, int index, double a, double r, double g, double b)
        {
            var p = new[] { r * a, g * a, b * a };
            for (var c = 0; c < 3; c++)
            {
                f.ColorOverBlack[index * 4 + c] = H(p[c]);
                f.ColorOverWhite[index * 4 + c] = H(p[c] + 1 - a);
            }
        }

        static RawFrame Frame()
        {
            // 2×4 samples at k = 2: two output pixels stacked; texture rows bottom-up, so samples 0–3 (rows 0, 1) are the bottom pixel.
            var f = new RawFrame(2, 4, 2) { ColorOverBlack = new ushort[2 * 4 * 4], ColorOverWhite = new ushort[2 * 4 * 4] };
            for (var i = 0; i < 8; i++) Sample(f, i, 0, 0, 0, 0);
            Sample(f, 0, 1, 2.0, 0.5, 0.25);   // bottom pixel: an opaque sample brighter than 1 …
            Sample(f, 1, 0.5, 1, 1, 1);        // … a half-covered white one, two empty
            for (var i = 4; i < 8; i++) Sample(f, i, 1, 0.25, 0.25, 0.25); // top pixel: opaque grey
            return f;
        }

        [Test]
        public void StraightLinearColourIsUnpremultipliedInFloatWithoutTheClip()
        {
            var hdr = HdrColour.Resolve(Frame());
            // Bottom pixel: Σa = 1.5, Σp = (2 + 0.5, 0.5 + 0.5, 0.25 + 0.5) → (5/3, 2/3, 1/2), alpha 1.5 / 4.
            Assert.That(hdr.Take(4), Is.EqualTo(new[] { 5.0 / 3, 2.0 / 3, 0.5, 0.375 }).Within(1e-6));
            Assert.That(hdr.Skip(4), Is.EqualTo(new[] { 0.25, 0.25, 0.25, 1.0 }).Within(1e-6), "rows stay bottom-up");

            // The PNG of the same frame is this, clipped and encoded: sRGB(1) = 255, sRGB(2/3) = 213, sRGB(1/2) = 188, alpha round(95.625) = 96.
            var png = new byte[8];
            DifferenceMatting.Resolve(Frame(), png, default, false);
            Assert.That(png.Skip(4), Is.EqualTo(new byte[] { 255, 213, 188, 96 }), "the PNG's top row is the bottom pixel");
            Assert.That(new[] { Srgb.EncodeByteExact(Math.Min(1, hdr[0])), Srgb.EncodeByteExact(hdr[1]), Srgb.EncodeByteExact(hdr[2]), (byte)Math.Floor(hdr[3] * 255 + 0.5) },
                Is.EqualTo(png.Skip(4)));
        }

        [Test]
        public void ASolidBackgroundIsCompositedWithAlphaOne()
        {
            var hdr = HdrColour.Resolve(Frame(), Background.SolidLinear(0, 0, 1));
            // Bottom: (2 + 0 + 0 + 0, 0.5, 0.25) for the colour, the half sample 0.5 + 0.5·B, empty ones B: / 4.
            Assert.That(hdr.Take(4), Is.EqualTo(new[] { 2.5 / 4, 1.0 / 4, (0.25 + 1 + 2) / 4, 1.0 }).Within(1e-6));
        }

        [Test]
        public void AGammaProjectAndAFrameWithoutThePairAreRefused()
        {
            var gamma = Frame();
            gamma.ColorIsGammaEncoded = true;
            var e = Assert.Throws<InvalidParameterException>(() => HdrColour.Resolve(gamma));
            Assert.That(e.Message, Does.Contain("Color Space to Linear"));
            var single = new RawFrame(2, 2, 1) { ColorLinear = new float[16] };
            e = Assert.Throws<InvalidParameterException>(() => HdrColour.Resolve(single));
            Assert.That(e.Message, Does.Contain("frame.ColorOverBlack"));
        }

        [Test]
        public void SettingsRoundTripAndRefusals()
        {
            var read = DatasetSettingsJson.Read("{ \"hdr\": { \"splits\": [\"train\", \"test\"] } }").Settings.Hdr;
            Assert.That((read.Enabled, read.Train, read.Val, read.Test), Is.EqualTo((true, true, false, true)));
            var s = new DatasetSettings();
            Assert.That(DatasetSettingsJson.Write(s), Does.Not.Contain("\"hdr\""), "off: the config keeps its keys");
            s.Hdr.On = true;
            s.Hdr.Val = false;
            var back = DatasetSettingsJson.Read(DatasetSettingsJson.Write(s)).Settings.Hdr;
            Assert.That((back.Enabled, back.Train, back.Val, back.Test), Is.EqualTo((true, true, false, true)));
            Assert.That(DatasetSettingsJson.Read("{ \"hdr\": { \"enabled\": false } }").Settings.Hdr.Enabled, Is.False);
            var bad = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"hdr\": { \"splits\": [\"tran\"] } }"));
            Assert.That(bad.Message, Does.Contain("hdr.splits[0]").And.Contain("train"));
            s.Hdr.Train = s.Hdr.Test = false;
            Assert.That(HdrSettingsValidator.Validate(s).Select(p => p.Field), Is.EqualTo(new[] { "hdr.splits" }));
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Train), Has.No.Member(DatasetFileKind.HdrExr));
            s.Hdr.Train = true;
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Train), Has.Member(DatasetFileKind.HdrExr));
            Assert.That(DatasetLayout.RelativePath(DatasetSplit.Train, 7, DatasetFileKind.HdrExr), Is.EqualTo("train/r_7_hdr.exr"));
        }

        [Test]
        public void TheWriterFlipsRowsAndTheReaderReadsThemBack()
        {
            // 3×2, texture order: bottom row first.
            var pixels = Enumerable.Range(0, 3 * 2 * 4).Select(i => i * 0.5f - 3).ToArray();
            var exr = ExrReader.Decode(ExrWriter.Encode(pixels, 3, 2, 4), "t.exr");
            Assert.That((exr.Width, exr.Height), Is.EqualTo((3, 2)));
            Assert.That(exr.Channels.Keys.OrderBy(k => k), Is.EqualTo(new[] { "A", "B", "G", "R" }));
            // The file's first row (top) is the input's second row.
            Assert.That(exr.Channel("R"), Is.EqualTo(new[] { pixels[12], pixels[16], pixels[20], pixels[0], pixels[4], pixels[8] }));
            Assert.That(exr.Channel("A"), Is.EqualTo(new[] { pixels[15], pixels[19], pixels[23], pixels[3], pixels[7], pixels[11] }));
            var depth = ExrReader.Decode(ExrWriter.Encode(new[] { 1f, 2f }, 1, 2, 1), "d.exr");
            Assert.That(depth.Channel("Y"), Is.EqualTo(new[] { 2f, 1f }));
        }

        /// <summary>
        /// An EXR with ZIP compression (16 lines a block) of HALF channels, made here as OpenEXR's ImfZip.cpp compresses:
        /// bytes split into even and odd halves, then each byte minus the previous plus 128, then zlib.
        /// </summary>
        static byte[] ZipExr(ushort[][] channels, string[] names, int width, int height)
        {
            var s = new MemoryStream();
            var w = new BinaryWriter(s);
            w.Write(new byte[] { 0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0 });
            void Attr(string name, string type, byte[] value)
            {
                w.Write(System.Text.Encoding.ASCII.GetBytes(name + "\0" + type + "\0"));
                w.Write(value.Length);
                w.Write(value);
            }
            var list = new MemoryStream();
            foreach (var name in names)
            {
                list.Write(System.Text.Encoding.ASCII.GetBytes(name + "\0"));
                list.Write(BitConverter.GetBytes(1)); list.Write(new byte[4]); list.Write(BitConverter.GetBytes(1)); list.Write(BitConverter.GetBytes(1));
            }
            list.WriteByte(0);
            Attr("channels", "chlist", list.ToArray());
            Attr("compression", "compression", new byte[] { 3 });
            var box = new byte[16];
            BitConverter.GetBytes(width - 1).CopyTo(box, 8);
            BitConverter.GetBytes(height - 1).CopyTo(box, 12);
            Attr("dataWindow", "box2i", box);
            Attr("displayWindow", "box2i", box);
            Attr("lineOrder", "lineOrder", new byte[] { 0 });
            w.Write((byte)0);
            var blocks = (height + 15) / 16;
            var tablePosition = s.Position;
            w.Write(new byte[8 * blocks]);
            var offsets = new long[blocks];
            for (var block = 0; block < blocks; block++)
            {
                var raw = new MemoryStream();
                for (var y = block * 16; y < Math.Min(height, block * 16 + 16); y++)
                    foreach (var channel in channels)
                        for (var x = 0; x < width; x++) raw.Write(BitConverter.GetBytes(channel[y * width + x]));
                var bytes = raw.ToArray();
                var t = new byte[bytes.Length];
                int even = 0, odd = (bytes.Length + 1) / 2;
                for (var i = 0; i < bytes.Length; i++) t[(i & 1) == 0 ? even++ : odd++] = bytes[i];
                for (var i = t.Length - 1; i > 0; i--) t[i] = (byte)(t[i] - t[i - 1] + 128);
                var z = new MemoryStream();
                z.WriteByte(0x78); z.WriteByte(0x9C);
                using (var deflate = new DeflateStream(z, CompressionLevel.Optimal, true)) deflate.Write(t, 0, t.Length);
                var adler = Adler32.Compute(t, 0, t.Length);
                Assert.That(z.Length + 4, Is.LessThan(bytes.Length), "the block is stored compressed");
                z.Write(new[] { (byte)(adler >> 24), (byte)(adler >> 16), (byte)(adler >> 8), (byte)adler });
                offsets[block] = s.Position;
                w.Write(block * 16);
                w.Write((int)z.Length);
                w.Write(z.ToArray());
            }
            s.Position = tablePosition;
            foreach (var offset in offsets) w.Write(offset);
            return s.ToArray();
        }

        [Test]
        public void ZipCompressedHalfChannelsAreRead()
        {
            int width = 5, height = 20; // two blocks, the second of 4 lines
            // Smooth values (a ramp per channel) compress, as real images do: a block that would not is stored raw instead.
            var values = Enumerable.Range(0, 4).Select(c => Enumerable.Range(0, width * height).Select(i => H((i % width) * 0.25 + (i / width) * 0.125 - c)).ToArray()).ToArray();
            var exr = ExrReader.Decode(ZipExr(values, new[] { "A", "B", "G", "R" }, width, height), "zip.exr");
            Assert.That(exr.Channel("G"), Is.EqualTo(values[2].Select(HalfFloat.ToFloat).ToArray()));
            Assert.That(exr.Channel("A"), Is.EqualTo(values[0].Select(HalfFloat.ToFloat).ToArray()));
            var e = Assert.Throws<InvalidDataException>(() => ExrReader.Decode(new byte[] { 1, 2, 3, 4, 5, 6, 7, 8 }, "bad.exr"));
            Assert.That(e.Message, Does.Contain("bad.exr"));
        }
    }
}
