using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>URP renderer features in the capture's colour renders (review S3-1): which are refused, warned or let through.</summary>
    public class RendererFeatureCheckTests
    {
        static RendererFeatureInfo Feature(string name, bool active, params string[] types) => new RendererFeatureInfo(name, types, active);

        static (List<ValidationProblem> Errors, List<ValidationProblem> Warnings) Check(bool sky, params RendererFeatureInfo[] features)
        {
            var errors = new List<ValidationProblem>();
            var warnings = new List<ValidationProblem>();
            RendererFeatureCheck.Check("\"PC_Renderer\"", features, sky, errors, warnings);
            return (errors, warnings);
        }

        [Test]
        public void URPsGeometryOnlyFeaturesPassSilently()
        {
            var (errors, warnings) = Check(false,
                Feature("SSAO", true, "ScreenSpaceAmbientOcclusion", "ScriptableRendererFeature"),
                Feature("Decals", true, "DecalRendererFeature", "ScriptableRendererFeature"),
                Feature("Shadows", true, "ScreenSpaceShadows", "ScriptableRendererFeature"));
            Assert.That(errors, Is.Empty);
            Assert.That(warnings, Is.Empty);
        }

        [Test]
        public void AnActiveFullScreenPassIsRefusedWithTheFixNamed()
        {
            var (errors, warnings) = Check(false,
                Feature("Vignette", true, "FullScreenPassRendererFeature", "ScriptableRendererFeature"),
                Feature("Old tint", false, "FullScreenPassRendererFeature", "ScriptableRendererFeature"));
            Assert.That(errors.Count, Is.EqualTo(1), "the unticked one never runs");
            Assert.That(errors[0].Value, Is.EqualTo("\"PC_Renderer\" ▸ Vignette"));
            Assert.That(errors[0].Reason, Does.Contain("Full Screen Pass").And.Contain("over black and over white"));
            Assert.That(errors[0].Fix, Does.Contain("Untick \"Vignette\"").And.Contain("Default Renderer"));
            Assert.That(warnings, Is.Empty);
        }

        [Test]
        public void ASubclassOfFullScreenPassIsOneAndASkyBackgroundNeedsNoMatting()
        {
            var subclass = Feature("Custom", true, "MyFullScreen", "FullScreenPassRendererFeature", "ScriptableRendererFeature");
            Assert.That(Check(false, subclass).Errors.Count, Is.EqualTo(1));
            var (errors, warnings) = Check(true, subclass);
            Assert.That(errors, Is.Empty, "a sky is rendered once, alpha 255 everywhere");
            Assert.That(warnings, Is.Empty);
        }

        [Test]
        public void UnknownFeaturesGetOneWarningNamingEach()
        {
            var (errors, warnings) = Check(false,
                Feature("Outline", true, "OutlineFeature", "ScriptableRendererFeature"),
                Feature("Render Objects", true, "RenderObjects", "ScriptableRendererFeature"),
                Feature("Off", false, "PixelateFeature", "ScriptableRendererFeature"));
            Assert.That(errors, Is.Empty);
            Assert.That(warnings.Count, Is.EqualTo(1));
            Assert.That(warnings[0].Reason, Does.Contain("\"Outline\" (OutlineFeature), \"Render Objects\" (RenderObjects)").And.Not.Contain("Pixelate"));
            Assert.That(warnings[0].Fix, Does.Contain("Matting"));
        }
    }
}
