using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class MaterialValuesTests
    {
        // Three samples: 0 not covered by a supported shader (values present but must not be used), 1 a metallic-workflow
        // material, 2 a specular-setup material. Coverage bytes: R = supported, G = specular setup.
        static readonly byte[] Coverage = { 0, 0, 0, 0, 255, 0, 0, 255, 255, 255, 0, 255 };

        static ushort[] Halves(params float[] values)
        {
            var h = new ushort[values.Length];
            for (var i = 0; i < h.Length; i++) h[i] = HalfFloat.FromFloat(values[i]);
            return h;
        }

        [Test]
        public void ColourIsCopiedWhereSupportedAndZeroElsewhere()
        {
            var rgba = Halves(0.9f, 0.9f, 0.9f, 1f, 0.5f, 0.25f, 1f, 1f, 0.125f, 0.75f, 0f, 1f);
            var albedo = MaterialValues.Colour(rgba, Coverage, gammaProject: false, specularSetupOnly: false);
            Assert.That(albedo, Is.EqualTo(new[] { 0f, 0f, 0f, 0f, 0.5f, 0.25f, 1f, 1f, 0.125f, 0.75f, 0f, 1f }));
        }

        [Test]
        public void GammaProjectsDecodeColoursWithTheSrgbCurve()
        {
            var rgba = Halves(0f, 0f, 0f, 1f, 0.5f, 0.04f, 1f, 1f, 0f, 0f, 0f, 1f);
            var albedo = MaterialValues.Colour(rgba, Coverage, gammaProject: true, specularSetupOnly: false);
            // ((0.5 + 0.055) / 1.055)^2.4 = 0.2140411; 0.04 / 12.92 = 0.0030960; 1 stays 1.
            Assert.That(albedo[4], Is.EqualTo(0.2140411f).Within(1e-6f));
            Assert.That(albedo[5], Is.EqualTo(0.04f / 12.92f).Within(1e-5f));
            Assert.That(albedo[6], Is.EqualTo(1f));
        }

        [Test]
        public void SpecularColourIsKeptOnlyForSpecularSetupMaterials()
        {
            var rgba = Halves(0f, 0f, 0f, 1f, 0.04f, 0.04f, 0.04f, 1f, 0.5f, 0.5f, 0.5f, 1f);
            var specular = MaterialValues.Colour(rgba, Coverage, false, specularSetupOnly: true);
            Assert.That(specular, Is.EqualTo(new[] { 0f, 0f, 0f, 0f, 0f, 0f, 0f, 0f, 0.5f, 0.5f, 0.5f, 1f }));
        }

        [Test]
        public void MetallicIsZeroForSpecularSetupWhereUrpReportsOne()
        {
            var rgba = Halves(0.7f, 0, 0, 1, 0.25f, 0, 0, 1, 1f, 0, 0, 1);
            Assert.That(MaterialValues.Scalar(rgba, Coverage, roughness: false), Is.EqualTo(new[] { 0f, 0.25f, 0f }));
        }

        [Test]
        public void RoughnessIsOneMinusTheRenderedSmoothnessAndZeroWhereUncovered()
        {
            var rgba = Halves(0.7f, 0, 0, 1, 0.25f, 0, 0, 1, 0.875f, 0, 0, 1);
            Assert.That(MaterialValues.Scalar(rgba, Coverage, roughness: true), Is.EqualTo(new[] { 0f, 0.75f, 0.125f }));
        }
    }
}
