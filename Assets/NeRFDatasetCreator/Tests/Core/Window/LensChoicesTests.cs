using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The window's Lens section: the popup names the settings' models, and every field it draws is one the validator can report on.</summary>
    [TestFixture]
    public class LensChoicesTests
    {
        [Test]
        public void ThePopupHoldsEveryModelTheSettingsKnowInItsOrder()
        {
            Assert.That(LensChoices.ModelNames, Is.EqualTo(new[] { "none", "opencv", "opencv_fisheye" }));
            Assert.That(LensChoices.ModelLabels, Has.Length.EqualTo(LensChoices.ModelNames.Length));
            Assert.That(LensChoices.ModelNames.All(LensSettings.ModelNames.IsKnown), Is.True);
            Assert.That(LensChoices.IndexOf(null), Is.EqualTo(0), "a missing model is none, as LensSettings.Enabled reads it");
            Assert.That(LensChoices.IndexOf(" OpenCV_Fisheye "), Is.EqualTo(2));
            Assert.That(LensChoices.IndexOf("kannala"), Is.EqualTo(-1));
        }

        [TestCase("none", new string[0])]
        [TestCase("opencv", new[] { "k1", "k2", "p1", "p2", "k3" })]
        [TestCase("opencv_fisheye", new[] { "k1", "k2", "k3", "k4" })]
        public void EachModelShowsItsOwnCoefficients(string model, string[] expected)
        {
            Assert.That(LensChoices.Shown(new LensSettings { Model = model }), Is.EqualTo(expected));
        }

        [Test]
        public void AForeignCoefficientFromAConfigIsShownWhereItsErrorCanBeFixed()
        {
            var settings = new DatasetSettings();
            settings.Lens.Model = "opencv";
            settings.Lens.K4 = 0.02;
            var problem = LensSettingsValidator.Validate(settings).Single();
            Assert.That(problem.Field, Is.EqualTo("lens.k4"));
            Assert.That(LensChoices.Shown(settings.Lens).Select(LensChoices.Field), Has.Member(problem.Field));
            Assert.That(LensChoices.Tooltip("opencv", "k4"), Does.StartWith("Not a coefficient of this model"));
        }

        [Test]
        public void APinholeWithCoefficientsShowsNoFieldsItsErrorIsUnderTheModel()
        {
            var settings = new DatasetSettings();
            settings.Lens.K1 = -0.1; // a config's { "model": "none", "k1": -0.1 }
            Assert.That(LensChoices.Shown(settings.Lens), Is.Empty);
            Assert.That(LensSettingsValidator.Validate(settings).Select(p => p.Field), Is.EqualTo(new[] { LensChoices.Field("model") }));
            // The way out in the window: a model (the coefficients appear), then None, which clears them.
            LensChoices.ChangeModel(settings.Lens, "opencv");
            Assert.That(LensChoices.Shown(settings.Lens), Has.Member("k1"));
            LensChoices.ChangeModel(settings.Lens, "none");
            Assert.That(LensSettingsValidator.Validate(settings), Is.Empty);
        }

        [Test]
        public void ChangingTheModelKeepsSharedCoefficientsAndClearsTheOthers()
        {
            var lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.03, K3 = 0.001, P1 = 0.0005, P2 = -0.0003 };
            LensChoices.ChangeModel(lens, "opencv_fisheye");
            Assert.That(new[] { lens.K1, lens.K2, lens.K3, lens.K4, lens.P1, lens.P2 }, Is.EqualTo(new[] { -0.12, 0.03, 0.001, 0, 0, 0 }));
            Assert.That(lens.Model, Is.EqualTo("opencv_fisheye"));
            var settings = new DatasetSettings { Lens = lens, Loaders = TargetLoaders.Nerfstudio };
            Assert.That(LensSettingsValidator.Validate(settings), Is.Empty, "the fisheye keeps no tangential terms the validator refuses");

            LensChoices.ChangeModel(lens, "none");
            Assert.That(new[] { lens.K1, lens.K2, lens.K3, lens.K4, lens.P1, lens.P2 }, Is.All.EqualTo(0.0));
            Assert.That(LensSettingsValidator.Validate(settings), Is.Empty, "a pinhole with coefficients would be refused");
            Assert.That(() => LensChoices.ChangeModel(lens, "kannala"), Throws.ArgumentException);
        }

        [Test]
        public void EachCoefficientFieldReadsAndWritesItsOwnSetting()
        {
            var lens = new LensSettings();
            for (var i = 0; i < LensChoices.AllCoefficients.Length; i++) LensChoices.Set(lens, LensChoices.AllCoefficients[i], i + 1);
            Assert.That(new[] { lens.K1, lens.K2, lens.P1, lens.P2, lens.K3, lens.K4 }, Is.EqualTo(new double[] { 1, 2, 3, 4, 5, 6 }));
            Assert.That(LensChoices.AllCoefficients.Select(k => LensChoices.Get(lens, k)), Is.EqualTo(new double[] { 1, 2, 3, 4, 5, 6 }));
        }

        [Test]
        public void ACoefficientIsReportedUnderTheFieldTheSectionDraws()
        {
            var settings = new DatasetSettings();
            settings.Lens.Model = "opencv";
            settings.Lens.K2 = double.NaN;
            Assert.That(LensSettingsValidator.Validate(settings).Select(p => p.Field), Is.EqualTo(new[] { LensChoices.Field("k2") }));
        }
    }
}
