using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class NormalisationSettingsTests
    {
        [Test]
        public void DefaultsRecentreWithoutAPointCloud()
        {
            var s = new DatasetSettings();
            Assert.That(s.Normalisation, Is.EqualTo(NormalisationMode.Recentre));
            Assert.That(s.NormalisedTargetRadius, Is.EqualTo(1.0));
            Assert.That(s.PointCloudPoints, Is.EqualTo(0));
            Assert.That(SettingsValidator.Validate(s), Is.Empty);
        }

        [TestCase(NormalisationMode.None, "none")]
        [TestCase(NormalisationMode.Recentre, "recentre")]
        [TestCase(NormalisationMode.NerfSyntheticScale, "nerf-synthetic")]
        [TestCase(NormalisationMode.FitTargetRadius, "fit-radius")]
        public void TheNewKeysRoundTrip(NormalisationMode mode, string name)
        {
            var s = new DatasetSettings { Normalisation = mode, NormalisedTargetRadius = 0.1 + 0.2, PointCloudPoints = 123456 };
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text, Does.Contain("\"normalisation\": \"" + name + "\","));
            Assert.That(text, Does.Contain("\"normalisedTargetRadius\": 0.30000000000000004,"));
            Assert.That(text, Does.Contain("\"pointCloudPoints\": 123456,"));
            var read = DatasetSettingsJson.Read(text);
            Assert.That(read.Warnings, Is.Empty);
            Assert.That(read.Settings.Normalisation, Is.EqualTo(mode));
            Assert.That(read.Settings.NormalisedTargetRadius, Is.EqualTo(0.1 + 0.2));
            Assert.That(read.Settings.PointCloudPoints, Is.EqualTo(123456));
            Assert.That(DatasetSettingsJson.Write(read.Settings), Is.EqualTo(text));
        }

        [Test]
        public void AnUnknownModeNamesTheKeyAndTheChoices()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\n  \"normalisation\": \"scale\"\n}", "c.json"));
            Assert.That(e.Message, Does.Contain("normalisation"));
            Assert.That(e.Message, Does.Contain("\"fit-radius\""));
            Assert.That(e.Message, Does.Contain("c.json(2,"));
        }

        [Test]
        public void APointCountMustBeAWholeNumber()
        {
            Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"pointCloudPoints\": 1.5 }"));
        }

        [TestCase(double.NaN, "is not a finite number.")]
        [TestCase(0.0, "is outside the valid range [0.001, 1000] output units.")]
        [TestCase(-1.0, "is outside the valid range [0.001, 1000] output units.")]
        [TestCase(1e4, "is outside the valid range [0.001, 1000] output units.")]
        public void TheTargetRadiusIsRangeChecked(double radius, string reason)
        {
            var problems = SettingsValidator.Validate(new DatasetSettings { NormalisedTargetRadius = radius });
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "normalisedTargetRadius" }));
            Assert.That(problems[0].Reason, Is.EqualTo(reason));
            Assert.That(problems[0].Fix, Does.Contain("1.3"));
        }

        [Test]
        public void ANaNRadiusReadsBackSoValidationCanReportIt()
        {
            var s = DatasetSettingsJson.Read(DatasetSettingsJson.Write(new DatasetSettings { NormalisedTargetRadius = double.NaN })).Settings;
            Assert.That(double.IsNaN(s.NormalisedTargetRadius), Is.True);
        }

        [TestCase(-1)]
        [TestCase(10_000_001)]
        public void ThePointCountIsRangeChecked(int count)
        {
            var problems = SettingsValidator.Validate(new DatasetSettings { PointCloudPoints = count });
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "pointCloudPoints" }));
            Assert.That(problems[0].Fix, Does.Contain("10000000"));
        }

        [Test]
        public void AnUndefinedModeIsAProblem()
        {
            var problems = SettingsValidator.Validate(new DatasetSettings { Normalisation = (NormalisationMode)17 });
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "normalisation" }));
            Assert.That(problems[0].Value, Is.EqualTo("17"));
        }

        [Test]
        public void CloneCopiesTheNewFields()
        {
            var s = new DatasetSettings { Normalisation = NormalisationMode.FitTargetRadius, NormalisedTargetRadius = 1.3, PointCloudPoints = 5 };
            var copy = s.Clone();
            copy.Normalisation = NormalisationMode.None;
            copy.NormalisedTargetRadius = 2;
            copy.PointCloudPoints = 6;
            Assert.That(s.Normalisation, Is.EqualTo(NormalisationMode.FitTargetRadius));
            Assert.That(s.NormalisedTargetRadius, Is.EqualTo(1.3));
            Assert.That(s.PointCloudPoints, Is.EqualTo(5));
        }
    }
}
