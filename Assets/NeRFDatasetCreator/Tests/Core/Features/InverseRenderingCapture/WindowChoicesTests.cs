using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class InverseRenderingWindowChoicesTests
    {
        [Test]
        public void RotationsRoundTripThroughTheTextField()
        {
            Assert.That(RelightingChoices.FormatRotations(new double[] { 0, 90, 180, 270 }), Is.EqualTo("0, 90, 180, 270"));
            Assert.That(RelightingChoices.ParseRotations("0, 90 180;270", out var problem), Is.EqualTo(new double[] { 0, 90, 180, 270 }));
            Assert.That(problem, Is.Null);
            // Shown and read back unchanged, so drawing the field is not an edit.
            var odd = new double[] { 0.12345, 359.5 };
            Assert.That(RelightingChoices.ParseRotations(RelightingChoices.FormatRotations(odd), out _), Is.EqualTo(odd));
        }

        [Test]
        public void AWordOrNothingInTheRotationsIsRefusedWithTheFix()
        {
            Assert.That(RelightingChoices.ParseRotations("0, ninety", out var problem), Is.Null);
            Assert.That(problem, Does.Contain("'ninety'").And.Contain("0, 90, 180, 270"));
            Assert.That(RelightingChoices.ParseRotations("  ", out problem), Is.Null);
            Assert.That(problem, Does.Contain("at least one"));
        }

        [Test]
        public void NewConditionsGetTheFirstFreeName()
        {
            var existing = new List<LightingCondition> { new LightingCondition { Name = "env-1" }, new LightingCondition { Name = "light-1", Kind = LightingKind.Point } };
            Assert.That(RelightingChoices.NewCondition(LightingKind.Environment, existing).Name, Is.EqualTo("env-2"));
            var spot = RelightingChoices.NewCondition(LightingKind.Spot, existing);
            Assert.That(spot.Name, Is.EqualTo("light-2"));
            Assert.That(spot.Kind, Is.EqualTo(LightingKind.Spot));
        }

        [Test]
        public void RendersPerViewCountEachRotationAndEachLight()
        {
            var settings = new RelightingSettings
            {
                On = true,
                Conditions = new List<LightingCondition>
                {
                    new LightingCondition { Name = "sunset", Rotations = new double[] { 0, 90, 180, 270 } },
                    new LightingCondition { Name = "olat-00", Kind = LightingKind.Point },
                },
            };
            Assert.That(RelightingChoices.RendersPerView(settings), Is.EqualTo(5));
            settings.On = false;
            Assert.That(RelightingChoices.RendersPerView(settings), Is.EqualTo(0));
        }

        [Test]
        public void MaterialFilesPerViewFollowTheContractsTable()
        {
            // Default: albedo, metallic, roughness: 3 × (EXR + PNG) + the coverage PNG.
            Assert.That(MaterialPassChoices.FilesPerView(new MaterialPassSettings { On = true }), Is.EqualTo(7));
            // All five: 4 × 2 + emission's EXR + coverage.
            Assert.That(MaterialPassChoices.FilesPerView(new MaterialPassSettings { On = true, Specular = true, Emission = true }), Is.EqualTo(10));
            Assert.That(MaterialPassChoices.FilesPerView(new MaterialPassSettings()), Is.EqualTo(0));
            Assert.That(MaterialPassChoices.PipelineNote("Built-in"), Does.Contain("Standard (Specular setup)"));
            Assert.That(MaterialPassChoices.PipelineNote("UniversalRenderPipelineAsset"), Does.Contain("Rendering Debugger"));
        }
    }
}
