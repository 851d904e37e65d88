using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetSettingsJsonTests
    {
        static DatasetSettings Unusual()
        {
            var s = new DatasetSettings
            {
                Name = "lego_1600",
                OutputFolder = "../datasets",
                Scene = "Assets/Scenes/Lego.unity",
                Target = "World/Lego",
                AutoDistance = true,
                AutoDistanceMargin = 1.5,
                Width = 1600,
                Height = 900,
                Supersampling = 3,
                Background = BackgroundSettings.Parse("#102030"),
                Seed = -1234567890123L,
                Overwrite = OverwritePolicy.Replace,
                Loaders = TargetLoaders.InstantNgp | TargetLoaders.GaussianSplatting,
            };
            s.Camera.VerticalFovDegrees = 0.1 + 0.2; // 0.30000000000000004 must survive
            s.Camera.NearClip = 0.05;
            s.Camera.FarClip = 250;
            s.Camera.CopyFromCamera = "Main Camera";
            s.Train.Count = 7;
            s.Train.Formation = new FormationSettings { Kind = FormationKind.Halo, ElevationDegrees = 12.5, StartAzimuthDegrees = -30 };
            s.Val.Count = 0;
            s.Val.Formation = new FormationSettings { Kind = FormationKind.Sphere };
            s.Test.Count = 3;
            s.Test.Formation = new FormationSettings { Kind = FormationKind.Random, UpperHemisphereOnly = false };
            s.Test.Depth = ExtraOutput.PngAndExr;
            s.Test.Normal = ExtraOutput.Exr;
            s.Test.Mask = true;
            return s;
        }

        [Test]
        public void DefaultSettingsWriteExactlyTheGoldenFile()
        {
            var text = DatasetSettingsJson.Write(new DatasetSettings());
            Assert.That(text, Is.EqualTo(Fixtures.Text("golden", "default_settings.json").Replace("\r\n", "\n")));
        }

        [Test]
        public void WriteThenReadThenWriteIsIdentical()
        {
            var first = DatasetSettingsJson.Write(Unusual());
            var read = DatasetSettingsJson.Read(first);
            Assert.That(read.Warnings, Is.Empty);
            Assert.That(DatasetSettingsJson.Write(read.Settings), Is.EqualTo(first));
        }

        [Test]
        public void ReadRestoresEveryValue()
        {
            var s = DatasetSettingsJson.Read(DatasetSettingsJson.Write(Unusual())).Settings;
            Assert.That(s.Name, Is.EqualTo("lego_1600"));
            Assert.That(s.OutputFolder, Is.EqualTo("../datasets"));
            Assert.That(s.Scene, Is.EqualTo("Assets/Scenes/Lego.unity"));
            Assert.That(s.Target, Is.EqualTo("World/Lego"));
            Assert.That(s.AutoDistance, Is.True);
            Assert.That(s.AutoDistanceMargin, Is.EqualTo(1.5));
            Assert.That(s.Width, Is.EqualTo(1600));
            Assert.That(s.Height, Is.EqualTo(900));
            Assert.That(s.Supersampling, Is.EqualTo(3));
            Assert.That(s.Background.ToConfigString(), Is.EqualTo("#102030"));
            Assert.That(s.Seed, Is.EqualTo(-1234567890123L));
            Assert.That(s.Overwrite, Is.EqualTo(OverwritePolicy.Replace));
            Assert.That(s.Loaders, Is.EqualTo(TargetLoaders.InstantNgp | TargetLoaders.GaussianSplatting));
            Assert.That(s.Camera.VerticalFovDegrees, Is.EqualTo(0.1 + 0.2), "bit-exact round trip");
            Assert.That(s.Camera.NearClip, Is.EqualTo(0.05));
            Assert.That(s.Camera.FarClip, Is.EqualTo(250.0));
            Assert.That(s.Camera.CopyFromCamera, Is.EqualTo("Main Camera"));
            Assert.That(s.Train.Count, Is.EqualTo(7));
            Assert.That(s.Train.Formation.Kind, Is.EqualTo(FormationKind.Halo));
            Assert.That(s.Train.Formation.ElevationDegrees, Is.EqualTo(12.5));
            Assert.That(s.Train.Formation.StartAzimuthDegrees, Is.EqualTo(-30.0));
            Assert.That(s.Val.Count, Is.EqualTo(0));
            Assert.That(s.Val.Formation.Kind, Is.EqualTo(FormationKind.Sphere));
            Assert.That(s.Test.Formation.Kind, Is.EqualTo(FormationKind.Random));
            Assert.That(s.Test.Formation.UpperHemisphereOnly, Is.False);
            Assert.That(s.Test.Depth, Is.EqualTo(ExtraOutput.PngAndExr));
            Assert.That(s.Test.Normal, Is.EqualTo(ExtraOutput.Exr));
            Assert.That(s.Test.Mask, Is.True);
        }

        [Test]
        public void FixedDistanceIsANumberAndAutoIsTheWordAuto()
        {
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Contain("\"distance\": 4.0,"));
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings { AutoDistance = true }), Does.Contain("\"distance\": \"auto\","));
        }

        [Test]
        public void MissingKeysKeepTheirDefaults()
        {
            var s = DatasetSettingsJson.Read("{ \"schemaVersion\": 1, \"splits\": { \"test\": { \"count\": 8 } } }").Settings;
            Assert.That(s.Test.Count, Is.EqualTo(8));
            Assert.That(s.Test.Formation.Kind, Is.EqualTo(FormationKind.Orbit));
            Assert.That(s.Train.Count, Is.EqualTo(100));
            Assert.That(s.Width, Is.EqualTo(800));
        }

        [Test]
        public void UnknownKeysAreWarningsWithTheirPathAndLine()
        {
            var text = "{\n  \"schemaVersion\": 1,\n  \"widht\": 640,\n  \"splits\": {\n    \"train\": { \"count\": 5, \"colour\": true }\n  }\n}";
            var result = DatasetSettingsJson.Read(text);
            Assert.That(result.Settings.Train.Count, Is.EqualTo(5));
            Assert.That(result.Settings.Width, Is.EqualTo(800), "a misspelt key does not set anything");
            Assert.That(result.Warnings.Select(w => w.Field), Is.EqualTo(new[] { "widht", "splits.train.colour" }));
            Assert.That(result.Warnings[0].Reason, Does.Contain("line 3"));
            Assert.That(result.Warnings[1].Reason, Does.Contain("line 5"));
            Assert.That(result.Warnings[0].Fix, Does.Contain("width"), "the fix lists the known keys");
        }

        [Test]
        public void ParametersOfAnotherFormationAreWarnings()
        {
            var text = "{ \"splits\": { \"val\": { \"formation\": { \"kind\": \"halo\", \"elevationDegrees\": 20, \"turns\": 3 } } } }";
            var result = DatasetSettingsJson.Read(text);
            Assert.That(result.Settings.Val.Formation.ElevationDegrees, Is.EqualTo(20.0));
            Assert.That(result.Warnings, Has.Count.EqualTo(1));
            Assert.That(result.Warnings[0].Field, Is.EqualTo("splits.val.formation.turns"));
            Assert.That(result.Warnings[0].Reason, Does.Contain("halo"));
        }

        [Test]
        public void OtherSchemaVersionIsAWarning()
        {
            var result = DatasetSettingsJson.Read("{ \"schemaVersion\": 2 }");
            Assert.That(result.Warnings, Has.Count.EqualTo(1));
            Assert.That(result.Warnings[0].Field, Is.EqualTo("schemaVersion"));
        }

        [Test]
        public void MalformedJsonGivesLineAndColumn()
        {
            // A comma is missing at the end of line 2. Newtonsoft stops at the '"' of "height" on line 3; the
            // message points at the place to edit instead: the end of 800 on line 2 (column 14).
            var text = "{\n  \"width\": 800\n  \"height\": 600\n}";
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text, "lego.json"));
            Assert.That(e.Line, Is.EqualTo(2));
            Assert.That(e.Column, Is.EqualTo(14));
            Assert.That(e.Message, Does.StartWith("lego.json(2,14): a comma is missing"));
        }

        [Test]
        public void MissingValueGivesTheFieldAndLine()
        {
            // Newtonsoft reads "key": , as an undefined value rather than a syntax error; it is still refused.
            var text = "{\n  \"width\": 800,\n  \"height\": ,\n  \"seed\": 1\n}";
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text, "lego.json"));
            Assert.That(e.Field, Is.EqualTo("height"));
            Assert.That(e.Line, Is.EqualTo(3));
            Assert.That(e.Message, Does.Contain("missing"));
        }

        [Test]
        public void UnterminatedJsonGivesTheLastLine()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\n  \"width\": 800,\n"));
            Assert.That(e.Line, Is.EqualTo(3));
        }

        [Test]
        public void WronglyTypedValueNamesTheFieldAndItsPlace()
        {
            var text = "{\n  \"splits\": {\n    \"train\": {\n      \"count\": \"100\"\n    }\n  }\n}";
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text));
            Assert.That(e.Field, Is.EqualTo("splits.train.count"));
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Message, Does.Contain("whole number"));
        }

        [TestCase("{ \"splits\": { \"train\": { \"formation\": { \"kind\": \"spiral\" } } } }", "splits.train.formation.kind")]
        [TestCase("{ \"overwrite\": \"always\" }", "overwrite")]
        [TestCase("{ \"loaders\": [\"nerf\", \"colmap\"] }", "loaders[1]")]
        [TestCase("{ \"background\": \"white\" }", "background")]
        [TestCase("{ \"splits\": { \"test\": { \"depth\": \"tiff\" } } }", "splits.test.depth")]
        [TestCase("{ \"width\": 1e400 }", "width")]
        [TestCase("{ \"width\": 99999999999 }", "width")]
        public void UnknownEnumValuesAreFormatErrors(string text, string field)
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text));
            Assert.That(e.Field, Is.EqualTo(field));
        }

        [Test]
        public void DuplicateKeysAreRefused()
        {
            Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"width\": 8, \"width\": 16 }"));
        }

        [Test]
        public void NaNIsReadSoThatValidationReportsIt()
        {
            var s = new DatasetSettings { Distance = double.NaN };
            var text = DatasetSettingsJson.Write(s);
            var read = DatasetSettingsJson.Read(text).Settings;
            Assert.That(double.IsNaN(read.Distance), Is.True);
            Assert.That(SettingsValidator.Validate(read).Select(p => p.Field), Does.Contain("distance"));
        }

        [Test]
        public void WritingIgnoresTheCurrentCulture()
        {
            var saved = System.Globalization.CultureInfo.CurrentCulture;
            try
            {
                System.Globalization.CultureInfo.CurrentCulture = new System.Globalization.CultureInfo("de-DE");
                var text = DatasetSettingsJson.Write(new DatasetSettings { Distance = 4.5 });
                Assert.That(text, Does.Contain("\"distance\": 4.5,"));
                Assert.That(DatasetSettingsJson.Read(text).Settings.Distance, Is.EqualTo(4.5));
            }
            finally
            {
                System.Globalization.CultureInfo.CurrentCulture = saved;
            }
        }
    }
}
