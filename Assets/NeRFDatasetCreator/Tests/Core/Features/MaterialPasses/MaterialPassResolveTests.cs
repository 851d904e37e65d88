using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The view stage of the material passes and their encodings, on hand-derived numbers.</summary>
    [TestFixture]
    public class MaterialPassResolveTests
    {
        [Test]
        public void TheSrgbCurveAndTheLinearCodeOnHandNumbers()
        {
            // sRGB: 1.055 · 0.5^(1/2.4) − 0.055 = 0.73536 → 187.52 → 188; no curve: 127.5 → 128 (halves up).
            Assert.That(MaterialEncoding.SrgbByte(0.5f), Is.EqualTo(188));
            Assert.That(MaterialEncoding.LinearByte(0.5f), Is.EqualTo(128));
            // 0.2: sRGB 123.56 → 124, linear 51; 0.85: sRGB 237.39 → 237, linear 216.75 → 217.
            Assert.That(MaterialEncoding.SrgbByte(0.2f), Is.EqualTo(124));
            Assert.That(MaterialEncoding.LinearByte(0.2f), Is.EqualTo(51));
            Assert.That(MaterialEncoding.SrgbByte(0.85f), Is.EqualTo(237));
            Assert.That(MaterialEncoding.LinearByte(0.85f), Is.EqualTo(217));
            // Clamped: above 1 is 255, below 0 and NaN are 0.
            Assert.That(new[] { MaterialEncoding.LinearByte(1.5f), MaterialEncoding.LinearByte(-0.1f), MaterialEncoding.LinearByte(float.NaN) }, Is.EqualTo(new byte[] { 255, 0, 0 }));
        }

        [Test]
        public void EncodedPngsRoundTripToTheirValuesWithinHalfACode()
        {
            var values = new[] { 0f, 0.0031308f, 0.04f, 0.2f, 0.5f, 0.73f, 1f };
            foreach (var v in values)
            {
                var srgb = MaterialEncoding.PngBytes(new[] { v, v, v, 1f }, new byte[] { 255 }, MaterialPngEncoding.Srgb);
                var linear = MaterialEncoding.PngBytes(new[] { v, v, v, 1f }, new byte[] { 255 }, MaterialPngEncoding.Linear);
                Assert.That(Srgb.EncodeExact(v) * 255, Is.EqualTo((double)srgb[0]).Within(0.5 + 1e-6), "sRGB " + v);
                Assert.That(v * 255.0, Is.EqualTo((double)linear[0]).Within(0.5 + 1e-6), "linear " + v);
                Assert.That((srgb[3], linear[3]), Is.EqualTo(((byte)255, (byte)255)), "alpha is the given byte");
            }
        }

        /// <summary>
        /// One output pixel at k = 2 (samples bottom row first: [s0 s1] is the bottom row, [s2 s3] the top). Samples 0 and 1
        /// are covered (mask 255, supported), 2 is covered but by an unsupported shader, 3 is not covered and holds junk.
        /// </summary>
        static RawFrame EdgeBlock()
        {
            var frame = new RawFrame(2, 2, 2)
            {
                Mask = new byte[] { 255, 255, 255, 0 }, MaskBytesPerPixel = 1,
                MaterialSupported = new byte[] { 255, 255, 0, 0 },
                MaterialRoughness = new[] { 0.2f, 0.6f, 0.9f, 7f },
                MaterialAlbedo = new[] { 0.1f, 0.2f, 0.3f, 0f, 0.5f, 0.6f, 0.7f, 0f, 1f, 1f, 1f, 0f, 9f, 9f, 9f, 0f },
            };
            return frame;
        }

        [Test]
        public void AnEdgePixelIsTheCoverageWeightedMeanOfItsSupportedSamples()
        {
            var frame = EdgeBlock();
            var roughness = MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("roughness"), new byte[] { 191 });
            // (0.2 + 0.6) / 2 = 0.4, grey; the unsupported and the uncovered sample add nothing; A = 191 / 255.
            Assert.That(roughness, Is.EqualTo(new[] { 0.4f, 0.4f, 0.4f, 191 / 255f }).Within(1e-6));
            var albedo = MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("albedo"), new byte[] { 191 });
            Assert.That(albedo, Is.EqualTo(new[] { 0.3f, 0.4f, 0.5f, 191 / 255f }).Within(1e-6));
            // Partial coverage weights: mask 255 and 85 → (0.2·255 + 0.6·85) / 340 = 0.3.
            frame.Mask = new byte[] { 255, 85, 0, 0 };
            Assert.That(MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("roughness"), new byte[] { 85 })[0], Is.EqualTo(0.3f).Within(1e-6));
            // Two of four samples supported: round(510 / 4) = 128 (halves up).
            Assert.That(MaterialPassResolve.Coverage(EdgeBlock()), Is.EqualTo(new byte[] { 128 }));
        }

        [Test]
        public void WhereTheColourImageHasNoAlphaThePassIsZero()
        {
            Assert.That(MaterialPassResolve.Resolve(EdgeBlock(), MaterialPassFiles.Named("albedo"), new byte[] { 0 }), Is.EqualTo(new[] { 0f, 0f, 0f, 0f }));
            // Covered in the colour image but no supported sample: RGB 0 (not guessed), alpha kept.
            var frame = EdgeBlock();
            frame.MaterialSupported = new byte[4];
            Assert.That(MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("roughness"), new byte[] { 255 }), Is.EqualTo(new[] { 0f, 0f, 0f, 1f }));
        }

        [Test]
        public void RowsComeOutTopFirstAndTheExrOrderFlipsThemBack()
        {
            // k = 1, 1 × 2: sample 0 is the bottom row (readback order), so it is output row 1.
            var frame = new RawFrame(1, 2, 1)
            {
                Mask = new byte[] { 255, 255 }, MaskBytesPerPixel = 1, MaterialSupported = new byte[] { 255, 255 }, MaterialMetallic = new[] { 0.25f, 0.75f },
            };
            var top = MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("metallic"), new byte[] { 255, 255 });
            Assert.That(new[] { top[0], top[4] }, Is.EqualTo(new[] { 0.75f, 0.25f }));
            var exr = MaterialEncoding.ExrOrder(top, 1, 2);
            Assert.That(new[] { exr[0], exr[4] }, Is.EqualTo(new[] { 0.25f, 0.75f }));
        }

        [Test]
        public void AMissingOrShortPassIsRefusedNamingTheArray()
        {
            var frame = EdgeBlock();
            var missing = Assert.Throws<InvalidParameterException>(() => MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("metallic"), new byte[] { 255 }));
            Assert.That(missing.Message, Does.Contain("frame.MaterialMetallic"));
            frame.MaterialSupported = null;
            var unsupported = Assert.Throws<InvalidParameterException>(() => MaterialPassResolve.Coverage(frame));
            Assert.That(unsupported.Message, Does.Contain("frame.MaterialSupported"));
            frame = EdgeBlock();
            frame.MaterialAlbedo = new float[3];
            Assert.That(Assert.Throws<InvalidParameterException>(() => MaterialPassResolve.Resolve(frame, MaterialPassFiles.Named("albedo"), new byte[] { 255 })).Message,
                Does.Contain("frame.MaterialAlbedo").And.Contain("expected 16"));
        }
    }
}
