using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The one on/off convention of the optional outputs (Documentation~/settings.md, "Optional outputs"): every feature
    /// section accepts <c>"enabled": true|false</c>; false turns the feature off whatever the section's other keys say
    /// and wherever the key stands; true agrees with the forms that existed before it, which still read as they did.
    /// </summary>
    [TestFixture]
    public class FeatureSwitchTests
    {
        static DatasetSettings Read(string json) => DatasetSettingsJson.Read(json).Settings;

        static bool[] AllOn(DatasetSettings s) =>
            new[] { s.Lens.Enabled, s.Exposure.Enabled, s.Time.Enabled, s.Labels.Enabled, s.MotionBlur.Enabled, s.GeometryPack };

        // Each section in a form that turns its feature on without "enabled" (the forms configs have always used).
        const string LensOn = "\"model\": \"opencv\", \"k1\": -0.1";
        const string ExposureOn = "\"mode\": \"list\", \"values\": [{ \"ev\": 1, \"whiteBalance\": [1, 1, 1] }]";
        const string TimeOn = "\"mode\": \"monocular\", \"steps\": 4";
        const string LabelsOn = "\"classFrom\": \"layer\"";
        const string BlurOn = "\"shutter\": 0.25";
        const string PackOn = "\"everyStep\": true";

        static string Config(string enabledFirst, string enabledLast) =>
            "{ \"lens\": { " + enabledFirst + LensOn + enabledLast + " }," +
            " \"exposure\": { " + enabledFirst + ExposureOn + enabledLast + " }," +
            " \"time\": { " + enabledFirst + TimeOn + enabledLast + " }," +
            " \"labels\": { " + enabledFirst + LabelsOn + enabledLast + " }," +
            " \"motionBlur\": { " + enabledFirst + BlurOn + enabledLast + " }," +
            " \"geometryPack\": { " + enabledFirst + PackOn + enabledLast + " } }";

        [Test]
        public void EverySectionWithoutTheKeyIsOnAsBefore()
        {
            Assert.That(AllOn(Read(Config("", ""))), Is.EqualTo(new[] { true, true, true, true, true, true }));
        }

        [Test]
        public void EnabledFalseTurnsEveryFeatureOffWhereverTheKeyStands()
        {
            var first = Read(Config("\"enabled\": false, ", ""));
            var last = Read(Config("", ", \"enabled\": false"));
            Assert.That(AllOn(first), Is.EqualTo(new[] { false, false, false, false, false, false }));
            Assert.That(AllOn(last), Is.EqualTo(new[] { false, false, false, false, false, false }));
            // Off is off: the written config is the default one, with no feature section.
            Assert.That(DatasetSettingsJson.Write(first), Is.EqualTo(DatasetSettingsJson.Write(Read("{ \"geometryPack\": false }"))));
            Assert.That(DatasetSettingsJson.Write(first), Does.Not.Contain("\"lens\"").And.Not.Contain("\"exposure\"").And.Not.Contain("\"time\"")
                .And.Not.Contain("\"labels\"").And.Not.Contain("\"motionBlur\""));
        }

        [Test]
        public void EnabledTrueReadsTheSameAsTheSectionWithoutIt()
        {
            var with = DatasetSettingsJson.Read(Config("\"enabled\": true, ", ""));
            var without = DatasetSettingsJson.Read(Config("", ""));
            Assert.That(with.Warnings, Is.Empty);
            Assert.That(DatasetSettingsJson.Write(with.Settings), Is.EqualTo(DatasetSettingsJson.Write(without.Settings)));
            Assert.That(with.Settings.Lens.K1, Is.EqualTo(-0.1));
            Assert.That(with.Settings.Exposure.Mode, Is.EqualTo(ExposureMode.List));
            Assert.That(with.Settings.Time.Mode, Is.EqualTo(TimeMode.Monocular));
            Assert.That(with.Settings.Labels.ClassFrom, Is.EqualTo(ClassSource.Layer));
            Assert.That(with.Settings.MotionBlur.Shutter, Is.EqualTo(0.25));
            Assert.That(with.Settings.GeometryPackEveryStep, Is.True);
        }

        [Test]
        public void TheGeometryPacksSectionFormMeansWhatItsShortFormsMean()
        {
            Assert.That(Read("{ \"geometryPack\": { \"enabled\": false } }").GeometryPack, Is.False);
            var everyStep = Read("{ \"geometryPack\": { \"enabled\": true, \"everyStep\": true } }");
            Assert.That(DatasetSettingsJson.Write(everyStep), Is.EqualTo(DatasetSettingsJson.Write(Read("{ \"geometryPack\": \"everyStep\" }"))));
            Assert.That(DatasetSettingsJson.Write(everyStep), Does.Contain("\"geometryPack\": \"everyStep\""), "written in the short form, as before");
            var plain = Read("{ \"geometryPack\": {} }");
            Assert.That(plain.GeometryPack && !plain.GeometryPackEveryStep, Is.True, "the section asks for the pack, the start time's mesh");
            var e = Assert.Throws<SettingsFormatException>(() => Read("{ \"geometryPack\": { \"everyStep\": \"yes\" } }"));
            Assert.That(e.Field, Is.EqualTo("geometryPack.everyStep"));
        }

        [TestCase("{ \"lens\": { \"enabled\": true } }", "lens.enabled", "\"model\" is \"none\"")]
        [TestCase("{ \"lens\": { \"enabled\": true, \"model\": \"none\" } }", "lens.enabled", "\"model\" is \"none\"")]
        [TestCase("{ \"exposure\": { \"mode\": \"off\", \"enabled\": true } }", "exposure.enabled", "\"mode\" is \"off\"")]
        [TestCase("{ \"time\": { \"enabled\": true } }", "time.enabled", "\"mode\" is \"static\"")]
        public void EnabledTrueCannotChooseAModelOrModeTheSectionTurnsOff(string json, string field, string why)
        {
            var e = Assert.Throws<SettingsFormatException>(() => Read(json));
            Assert.That(e.Field, Is.EqualTo(field));
            Assert.That(e.Message, Does.Contain("is true, but " + why).And.Contain("or set \"enabled\": false."));
            Assert.That(e.Line, Is.EqualTo(1), "the error points at the key, with its line");
        }

        [TestCase("lens")]
        [TestCase("exposure")]
        [TestCase("time")]
        [TestCase("labels")]
        [TestCase("motionBlur")]
        [TestCase("geometryPack")]
        public void EnabledMustBeTrueOrFalse(string section)
        {
            var e = Assert.Throws<SettingsFormatException>(() => Read("{ \"" + section + "\": { \"enabled\": \"yes\" } }"));
            Assert.That(e.Field, Is.EqualTo(section + ".enabled"));
            Assert.That(e.Message, Does.Contain("must be true or false, not \"yes\"."));
        }

        [TestCase("lens")]
        [TestCase("exposure")]
        [TestCase("time")]
        [TestCase("labels")]
        [TestCase("motionBlur")]
        [TestCase("geometryPack")]
        public void AnUnknownKeyIsWarnedAboutWithEnabledAmongTheKnownOnes(string section)
        {
            var warnings = DatasetSettingsJson.Read("{ \"" + section + "\": { \"enabld\": false } }").Warnings;
            Assert.That(warnings.Select(w => w.Field), Is.EqualTo(new[] { section + ".enabld" }));
            Assert.That(warnings[0].Fix, Does.StartWith("Remove it or correct its spelling; the known keys here are: enabled, ").And.Contain("\"enabled\""));
        }

        [Test]
        public void AWrittenConfigWithEveryFeatureOnReadsBackToTheSameText()
        {
            var s = Read(Config("", ""));
            var written = DatasetSettingsJson.Write(s);
            Assert.That(DatasetSettingsJson.Write(Read(written)), Is.EqualTo(written));
            Assert.That(AllOn(Read(written)), Is.EqualTo(new[] { true, true, true, true, true, true }));
        }

        [TestCase("nerf-sample.json", false)]
        [TestCase("nerf-sample-dynamic.json", true)]
        [TestCase("nerf-sample-multiview.json", true)]
        public void TheSampleConfigsLoadAsTheySay(string name, bool dynamic)
        {
            var path = Path.Combine(Fixtures.Folder, "..", "..", "..", "..", "Samples", "NeRFSample", name);
            var read = DatasetSettingsJson.ReadFile(path);
            Assert.That(read.Warnings, Is.Empty);
            var s = read.Settings;
            Assert.That(AllOn(s), Is.EqualTo(new[] { false, false, dynamic, false, false, true }));
            Assert.That(DatasetSettingsJson.Write(Read(DatasetSettingsJson.Write(s))), Is.EqualTo(DatasetSettingsJson.Write(s)));
        }
    }
}
