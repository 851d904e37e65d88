using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class NormalEncodingTests
    {
        static byte[] EncodeOne(float x, float y, float z)
        {
            var frame = new RawFrame(1, 1, 1) { Normals = new[] { x, y, z, 1f } };
            var rgb = new byte[3];
            NormalEncoding.Encode(frame, rgb);
            return rgb;
        }

        // round((n·0.5 + 0.5)·255), halves up: −1 → 0, 0 → 127.5 → 128, +1 → 255.
        [TestCase(1f, 0f, 0f, 255, 128, 128)]
        [TestCase(-1f, 0f, 0f, 0, 128, 128)]
        [TestCase(0f, 1f, 0f, 128, 255, 128)]
        [TestCase(0f, -1f, 0f, 128, 0, 128)]
        [TestCase(0f, 0f, 1f, 128, 128, 255)]
        [TestCase(0f, 0f, -1f, 128, 128, 0)]
        public void AxisVectorsMapToTheExpectedRgb(float x, float y, float z, int r, int g, int b)
        {
            Assert.That(EncodeOne(x, y, z), Is.EqualTo(new[] { (byte)r, (byte)g, (byte)b }));
        }

        [Test]
        public void NegativeComponentsSurvive()
        {
            // (−0.6, 0, 0.8): 0.2·255 = 51, 127.5 → 128, 0.9·255 = 229.5 → 230. The original plugin clipped −0.6 to 0 (→128).
            Assert.That(EncodeOne(-0.6f, 0f, 0.8f), Is.EqualTo(new byte[] { 51, 128, 230 }));
        }

        [Test]
        public void BackgroundIsBlackAndEdgesArePointSampled()
        {
            // k = 2, two output pixels: the first block has a background sample first in order (lower-left) and
            // +Z elsewhere → +Z, not a shortened average; the second block is all background → (0,0,0).
            var frame = FrameBuilder.Frame(2, 1, 2);
            frame.Normals = new float[frame.Width * frame.Height * 3];
            frame.NormalFloatsPerPixel = 3;
            foreach (var (x, y) in new[] { (1, 1), (0, 0), (1, 0) })
                frame.Normals[3 * FrameBuilder.Index(frame, x, y) + 2] = 1f;
            var rgb = new byte[6];
            NormalEncoding.Encode(frame, rgb);
            Assert.That(rgb, Is.EqualTo(new byte[] { 128, 128, 255, 0, 0, 0 }));
        }

        /// <summary>
        /// At supersampling 1 every pixel is <see cref="NormalEncoding.Component"/> of its own sample, or (0,0,0) where
        /// the sample's squared length is not above 0.25 (NaN included) — whatever the width, the stride and the frame
        /// (the loop is written out for Mono); checked pixel by pixel on random unit normals mixed with background,
        /// ±1 exactly, values beyond ±1, infinities, NaN and short vectors.
        /// </summary>
        /// <summary>
        /// Supersampling 1 encodes normals of squared length below 4 with an integer clamp instead of Component's
        /// float tests: every component value within a few ulps of each byte's edge ((b − 128)/127.5), of ±1 and of
        /// ±2's neighbourhood, and [−2, 2] in steps of 1/256, in each of the three positions (both frames), and pixels
        /// whose squared length is just below and just above 4, give Component's bytes.
        /// </summary>
        [TestCase(false)]
        [TestCase(true)]
        public void OneSamplePerPixelIntegerClampEqualsComponentNearEveryEdge(bool unityWorld)
        {
            var values = new System.Collections.Generic.List<float>();
            void Around(float centre)
            {
                float v = centre;
                for (int i = 0; i < 4; i++) v = NextDown(v);
                for (int i = 0; i < 9; i++, v = NextUp(v)) values.Add(v);
            }
            // Component(v) = floor(v·127.5 + 128) steps where v·127.5 + 128 is a whole number b.
            for (int b = 0; b <= 256; b++) Around((float)((b - 128) / 127.5));
            for (int i = -512; i <= 512; i++) values.Add(i / 256f); // (−2, 2) in steps of 1/256: the clamps' ranges
            foreach (float edge in new[] { 1f, -1f, 1.99f, -1.99f, 1.9999999f, -1.9999999f, 0f }) Around(edge);
            // Each value in x, y and z in turn, with a partner component that keeps the squared length in (0.25, 4).
            int pixels = values.Count * 3 + 4;
            var normals = new float[pixels * 4];
            for (int i = 0; i < values.Count * 3; i++)
            {
                float v = values[i / 3], partner = System.Math.Abs(v) > 0.75f ? 0f : 0.9f;
                int at = i % 3, other = (at + 1) % 3;
                normals[i * 4 + at] = v;
                normals[i * 4 + other] = partner;
            }
            // Squared length just below 4 (components near ±1.1547) and just above it.
            float[][] edges = { new[] { 1.1547f, -1.1547f, 1.1547f }, new[] { -1.1548f, 1.1548f, -1.1548f }, new[] { 1.9999999f, 0.1f, 0f }, new[] { -2f, 0f, 0.0001f } };
            for (int i = 0; i < 4; i++)
                for (int c = 0; c < 3; c++) normals[(values.Count * 3 + i) * 4 + c] = edges[i][c];

            var rgb = new byte[pixels * 3];
            NormalEncoding.Encode(new RawFrame(pixels, 1, 1) { Normals = normals, NormalsInUnityWorld = unityWorld }, rgb);
            int yAt = unityWorld ? 2 : 1, zAt = 3 - yAt;
            for (int p = 0; p < pixels; p++)
            {
                float x = normals[p * 4], y = normals[p * 4 + yAt], z = normals[p * 4 + zAt];
                Assert.That(x * x + y * y + z * z, Is.GreaterThan(0.25f), "every pixel is a surface");
                Assert.That(new[] { rgb[p * 3], rgb[p * 3 + 1], rgb[p * 3 + 2] },
                    Is.EqualTo(new[] { NormalEncoding.Component(x), NormalEncoding.Component(y), NormalEncoding.Component(z) }), $"pixel {p} from ({x:R}, {y:R}, {z:R})");
            }
        }

        static float NextUp(float v) => v == 0 ? float.Epsilon : System.BitConverter.Int32BitsToSingle(System.BitConverter.SingleToInt32Bits(v) + (v > 0 ? 1 : -1));

        static float NextDown(float v) => -NextUp(-v);

        [TestCase(1, 1, 4, false)]
        [TestCase(3, 5, 4, true)]
        [TestCase(4, 3, 4, true)]
        [TestCase(4, 1, 3, false)]
        [TestCase(8, 7, 3, true)]
        [TestCase(13, 4, 4, false)]
        [TestCase(64, 9, 4, true)]
        [TestCase(36, 6, 3, false)]
        public void OneSamplePerPixelGivesEachPixelsComponents(int w, int h, int stride, bool unityWorld)
        {
            var random = new SeededRandom(w * 100 + h * 10 + stride);
            float[] specials = { 1f, -1f, 1.0000001f, -1.0000001f, 0.99999994f, -0.99999994f, 0f, -0f, 2f, -3f,
                float.PositiveInfinity, float.NegativeInfinity, float.NaN, 0.003921f, -0.003922f };
            var normals = new float[w * h * stride];
            for (int p = 0; p < w * h; p++)
            {
                int kind = (int)(random.NextUInt64() % 4);
                for (int c = 0; c < stride; c++)
                {
                    float v = (float)(random.NextDouble() * 2 - 1);
                    if (kind == 0) v = 0; // background
                    else if (kind == 1) v = specials[random.NextUInt64() % (ulong)specials.Length];
                    else if (kind == 2) v *= 0.4f; // short: background unless long enough
                    normals[p * stride + c] = v;
                }
            }
            var rgb = new byte[w * h * 3];
            NormalEncoding.Encode(new RawFrame(w, h, 1) { Normals = normals, NormalFloatsPerPixel = stride, NormalsInUnityWorld = unityWorld }, rgb);

            int yAt = unityWorld ? 2 : 1, zAt = unityWorld ? 1 : 2, covered = 0;
            for (int oy = 0; oy < h; oy++)
                for (int ox = 0; ox < w; ox++)
                {
                    int n = ((h - 1 - oy) * w + ox) * stride, o = (oy * w + ox) * 3;
                    float x = normals[n], y = normals[n + yAt], z = normals[n + zAt];
                    bool surface = x * x + y * y + z * z > 0.25f;
                    if (surface) covered++;
                    var expected = surface ? new[] { NormalEncoding.Component(x), NormalEncoding.Component(y), NormalEncoding.Component(z) } : new byte[3];
                    Assert.That(new[] { rgb[o], rgb[o + 1], rgb[o + 2] }, Is.EqualTo(expected), $"pixel ({ox}, {oy}) from ({x}, {y}, {z})");
                }
            if (w * h >= 16) Assert.That(covered, Is.InRange(1, w * h - 1), "the input mixes surface and background");
        }

        [TestCase(1)]
        [TestCase(2)]
        public void UnityWorldNormalsGiveTheSameBytesAsRelabellingFirst(int k)
        {
            // The capture hands Unity world normals over with NormalsInUnityWorld; the encoders must swap y and z
            // while reading, giving exactly what NormalFrames.ToOutputWorld followed by the encoder gives.
            const int w = 5, h = 3;
            var random = new SeededRandom(8);
            var unity = new float[w * k * h * k * 4];
            for (int p = 0; p < unity.Length / 4; p++)
            {
                if (p % 7 == 3) continue; // background
                double x = random.NextDouble() * 2 - 1, y = random.NextDouble() * 2 - 1, z = random.NextDouble() * 2 - 1;
                double length = System.Math.Sqrt(x * x + y * y + z * z);
                unity[4 * p] = (float)(x / length);
                unity[4 * p + 1] = (float)(y / length);
                unity[4 * p + 2] = (float)(z / length);
            }
            var relabelled = (float[])unity.Clone();
            NormalFrames.ToOutputWorld(relabelled);

            var expectedRgb = new byte[w * h * 3];
            var actualRgb = new byte[w * h * 3];
            NormalEncoding.Encode(new RawFrame(w * k, h * k, k) { Normals = relabelled }, expectedRgb);
            NormalEncoding.Encode(new RawFrame(w * k, h * k, k) { Normals = unity, NormalsInUnityWorld = true }, actualRgb);
            Assert.That(actualRgb, Is.EqualTo(expectedRgb));
            Assert.That(actualRgb, Is.Not.EqualTo(new byte[actualRgb.Length]));

            var expectedFloats = new float[w * h * 4];
            var actualFloats = new float[w * h * 4];
            NormalEncoding.ToFloats(new RawFrame(w * k, h * k, k) { Normals = relabelled }, expectedFloats, RowDirection.TopRowFirst);
            NormalEncoding.ToFloats(new RawFrame(w * k, h * k, k) { Normals = unity, NormalsInUnityWorld = true }, actualFloats, RowDirection.TopRowFirst);
            Assert.That(actualFloats, Is.EqualTo(expectedFloats));
        }
    }
}
