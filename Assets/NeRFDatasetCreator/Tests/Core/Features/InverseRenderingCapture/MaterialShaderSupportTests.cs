using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class MaterialShaderSupportTests
    {
        static MaterialSnapshot Material(string shader, params string[] keywords)
        {
            var m = new MaterialSnapshot(shader);
            foreach (var k in keywords) m.WithKeyword(k);
            return m;
        }

        [Test]
        public void BuiltInReadsBothStandardShadersAndNothingElse()
        {
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, Material("Standard")), Is.Null);
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, Material("Standard (Specular setup)", "_SPECGLOSSMAP")), Is.Null);
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, Material("Custom/Toon")), Does.Contain("'Custom/Toon'"));
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, Material("Universal Render Pipeline/Lit")), Is.Not.Null);
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, null), Does.Contain("empty"));
        }

        [Test]
        public void StandardWithDetailOrHeightMapsIsNotGuessed()
        {
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, Material("Standard", "_DETAIL_MULX2")), Does.Contain("detail maps"));
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.BuiltIn, Material("Standard", "_PARALLAXMAP")), Does.Contain("parallax"));
        }

        [Test]
        public void UrpReadsLitAndComplexLitOnly()
        {
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.Urp, Material("Universal Render Pipeline/Lit")), Is.Null);
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.Urp, Material("Universal Render Pipeline/Complex Lit")), Is.Null);
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.Urp, Material("Universal Render Pipeline/Simple Lit")), Is.Not.Null);
            Assert.That(MaterialShaderSupport.WhyUnsupported(MaterialPipeline.Urp, Material("Standard")), Is.Not.Null);
        }

        [Test]
        public void SpecularSetupIsTheSpecularShaderInBuiltInAndTheKeywordInUrp()
        {
            Assert.That(MaterialShaderSupport.IsSpecularSetup(MaterialPipeline.BuiltIn, Material("Standard (Specular setup)")), Is.True);
            Assert.That(MaterialShaderSupport.IsSpecularSetup(MaterialPipeline.BuiltIn, Material("Standard")), Is.False);
            Assert.That(MaterialShaderSupport.IsSpecularSetup(MaterialPipeline.Urp, Material("Universal Render Pipeline/Lit", "_SPECULAR_SETUP")), Is.True);
            Assert.That(MaterialShaderSupport.IsSpecularSetup(MaterialPipeline.Urp, Material("Universal Render Pipeline/Lit")), Is.False);
        }

        [Test]
        public void RoughnessIsOneMinusSmoothness()
        {
            Assert.That(MaterialShaderSupport.RoughnessFromSmoothness(0.25f), Is.EqualTo(0.75f));
            Assert.That(MaterialShaderSupport.RoughnessFromSmoothness(1f), Is.EqualTo(0f));
            Assert.That(MaterialShaderSupport.RoughnessFromSmoothness(1.5f), Is.EqualTo(0f), "clamped");
        }

        [Test]
        public void TheReportListsShadersSortedWithTheirReasons()
        {
            var report = new MaterialShaderReport(MaterialPipeline.BuiltIn, new[] { "Standard (Specular setup)", "Standard" },
                new[] { new KeyValuePair<string, string>("Custom/Toon", "not Standard") });
            var json = report.ToJson();
            Assert.That((string)json["pipeline"], Is.EqualTo("builtin"));
            Assert.That(json["supported_shaders"].ToObject<string[]>(), Is.EqualTo(new[] { "Standard", "Standard (Specular setup)" }));
            Assert.That(json["unsupported_shaders"].ToObject<string[]>(), Is.EqualTo(new[] { "Custom/Toon" }));
            Assert.That(report.Warning(), Does.Contain("Custom/Toon (not Standard)"));
            Assert.That(new MaterialShaderReport(MaterialPipeline.Urp, new[] { "Universal Render Pipeline/Lit" }, null).Warning(), Is.Null);
        }
    }
}
