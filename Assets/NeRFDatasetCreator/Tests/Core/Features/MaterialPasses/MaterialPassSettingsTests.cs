using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The "materials" settings section: round trip, the one on/off convention, refusals naming the key, and the files a view gets.</summary>
    [TestFixture]
    public class MaterialPassSettingsTests
    {
        [Test]
        public void GivingTheSectionTurnsItOnWithTheDefaultPasses()
        {
            var m = DatasetSettingsJson.Read("{ \"materials\": {} }").Settings.Materials;
            Assert.That((m.Enabled, m.Albedo, m.Metallic, m.Roughness, m.Specular, m.Emission), Is.EqualTo((true, true, true, true, false, false)));
            Assert.That(DatasetSettingsJson.Read("{ \"materials\": { \"enabled\": false, \"passes\": [\"albedo\"] } }").Settings.Materials.Enabled, Is.False);
            Assert.That(new DatasetSettings().Materials.Enabled, Is.False, "off by default");
        }

        [Test]
        public void ThePassesRoundTripAndAreWrittenOnlyWhenOn()
        {
            var s = new DatasetSettings();
            Assert.That(DatasetSettingsJson.Write(s), Does.Not.Contain("\"materials\""), "off: the config keeps its keys");
            var read = DatasetSettingsJson.Read("{ \"materials\": { \"passes\": [\"emission\", \"roughness\", \"specular\"] } }").Settings;
            Assert.That((read.Materials.Albedo, read.Materials.Metallic, read.Materials.Roughness, read.Materials.Specular, read.Materials.Emission),
                Is.EqualTo((false, false, true, true, true)));
            var text = DatasetSettingsJson.Write(read);
            // Written in the one order of the passes, whatever order the file gave.
            Assert.That(System.Text.RegularExpressions.Regex.Replace(text, "\\s+", ""), Does.Contain("\"materials\":{\"passes\":[\"roughness\",\"specular\",\"emission\"]}"));
            var back = DatasetSettingsJson.Read(text).Settings.Materials;
            Assert.That((back.Enabled, back.Albedo, back.Roughness, back.Specular, back.Emission), Is.EqualTo((true, false, true, true, true)));
        }

        [Test]
        public void AnUnknownPassIsRefusedNamingTheKeyAndTheClosestName()
        {
            var bad = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"materials\": { \"passes\": [\"albedo\", \"rougness\"] } }"));
            Assert.That(bad.Message, Does.Contain("materials.passes[1]").And.Contain("is not a material pass").And.Contain("roughness"));
            var notAList = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"materials\": { \"passes\": \"albedo\" } }"));
            Assert.That(notAList.Message, Does.Contain("materials.passes").And.Contain("must be a list of pass names"));
        }

        [Test]
        public void AnEmptyListIsRefusedByTheValidatorNamingTheKeyAndTheFix()
        {
            var s = DatasetSettingsJson.Read("{ \"materials\": { \"passes\": [] } }").Settings;
            var problems = SettingsValidator.Validate(s).Where(p => p.Field.StartsWith("materials")).ToList();
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "materials.passes" }));
            Assert.That(problems[0].ToString(), Does.Contain("is empty").And.Contain("remove the \"materials\" section"));
            s.Materials.On = false;
            Assert.That(MaterialPassSettingsValidator.Validate(s), Is.Empty, "off: nothing to refuse");
        }

        [Test]
        public void AViewGetsTheFilesOfThePassesThatAreOnAndTheCoverage()
        {
            var s = new DatasetSettings();
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Test).Any(k => k >= DatasetFileKind.AlbedoExr), Is.False);
            s.Materials.On = true;
            s.Materials.Metallic = false;
            s.Materials.Emission = true;
            var kinds = DatasetLayout.FileKinds(s, DatasetSplit.Test).Where(k => k >= DatasetFileKind.AlbedoExr);
            Assert.That(kinds, Is.EqualTo(new[]
            {
                DatasetFileKind.AlbedoExr, DatasetFileKind.AlbedoPng, DatasetFileKind.RoughnessExr, DatasetFileKind.RoughnessPng,
                DatasetFileKind.EmissionExr, DatasetFileKind.MaterialCoveragePng,
            }));
            Assert.That(kinds.Select(k => DatasetLayout.RelativePath(DatasetSplit.Test, 7, k)), Is.EqualTo(new[]
            {
                "test/r_7_albedo.exr", "test/r_7_albedo.png", "test/r_7_roughness.exr", "test/r_7_roughness.png", "test/r_7_emission.exr", "test/r_7_material_coverage.png",
            }));
        }
    }
}
