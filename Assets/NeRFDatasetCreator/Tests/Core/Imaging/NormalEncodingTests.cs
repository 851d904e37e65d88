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
