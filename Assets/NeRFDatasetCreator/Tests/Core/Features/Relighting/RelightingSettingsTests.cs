using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The "relighting" section: its config form, the on/off convention, and every refusal naming its key and the fix.</summary>
    [TestFixture]
    public class RelightingSettingsTests
    {
        const string Contract = @"{ ""relighting"": { ""conditions"": [
           { ""name"": ""sunset"", ""kind"": ""environment"", ""file"": ""Assets/HDRI/sunset.exr"", ""rotations"": [0, 90, 180, 270], ""intensity"": 1 },
           { ""name"": ""olat-00"", ""kind"": ""point"", ""position"": [0, -3, 3], ""intensity"": 20, ""colour"": [1, 1, 1], ""shadows"": true },
           { ""name"": ""key"", ""kind"": ""spot"", ""position"": [2, 2, 3], ""direction"": [-2, -2, -3], ""spotAngle"": 30, ""intensity"": 30 } ] } }";

        static DatasetSettings Read(string json) => DatasetSettingsJson.Read(json).Settings;

        static IEnumerable<ValidationProblem> Problems(DatasetSettings s) => SettingsValidator.Validate(s).Where(p => p.Field.StartsWith("relighting"));

        [Test]
        public void TheContractsExampleReadsWritesAndReadsBackTheSame()
        {
            var s = Read(Contract);
            Assert.That(s.Relighting.Enabled, Is.True);
            Assert.That(Problems(s), Is.Empty);
            var c = s.Relighting.Conditions;
            Assert.That(c.Select(x => x.Kind), Is.EqualTo(new[] { LightingKind.Environment, LightingKind.Point, LightingKind.Spot }));
            Assert.That(c[0].Rotations, Is.EqualTo(new double[] { 0, 90, 180, 270 }));
            Assert.That(c[2].Direction, Is.EqualTo(new double[] { -2, -2, -3 }));
            Assert.That(LightingKeys.All(s), Is.EqualTo(new[] { "sunset_000", "sunset_090", "sunset_180", "sunset_270", "olat-00", "key" }));
            var text = DatasetSettingsJson.Write(s);
            var again = Read(text);
            Assert.That(DatasetSettingsJson.Write(again), Is.EqualTo(text));
            var section = (JObject)JObject.Parse(text)["relighting"];
            Assert.That(section["conditions"][0]["position"], Is.Null, "an environment has no position");
            Assert.That(section["conditions"][1]["rotations"], Is.Null, "a point light has no rotations");
        }

        [Test]
        public void OffByDefaultAndEnabledFalseWritesNothing()
        {
            Assert.That(JObject.Parse(DatasetSettingsJson.Write(new DatasetSettings()))["relighting"], Is.Null);
            var off = Read(@"{ ""relighting"": { ""enabled"": false, ""conditions"": [ { ""name"": ""a"", ""kind"": ""point"" } ] } }");
            Assert.That(off.Relighting.Enabled, Is.False);
            Assert.That(LightingKeys.All(off), Is.Empty);
            Assert.That(JObject.Parse(DatasetSettingsJson.Write(off))["relighting"], Is.Null);
            Assert.That(DatasetLayout.FileKinds(off, DatasetSplit.Train), Has.No.Member(DatasetFileKind.RelitPng));
        }

        [Test]
        public void AKeyOfAnotherKindIsRefusedByName()
        {
            var e = Assert.Throws<SettingsFormatException>(() => Read(@"{ ""relighting"": { ""conditions"": [ { ""name"": ""a"", ""kind"": ""point"", ""rotations"": [0] } ] } }"));
            Assert.That(e.Field, Is.EqualTo("relighting.conditions[0].rotations"));
            Assert.That(e.Message, Does.Contain("is not a key of a point light").And.Contain("change \"kind\""));
            var kind = Assert.Throws<SettingsFormatException>(() => Read(@"{ ""relighting"": { ""conditions"": [ { ""name"": ""a"", ""kind"": ""area"" } ] } }"));
            Assert.That(kind.Field, Is.EqualTo("relighting.conditions[0].kind"));
            Assert.That(kind.Message, Does.Contain("\"environment\", \"point\" or \"spot\""));
        }

        [Test]
        public void RotationsAreWholeUniqueDegreesBelow360()
        {
            var s = Read(@"{ ""relighting"": { ""conditions"": [ { ""name"": ""a"", ""kind"": ""point"" }, { ""name"": ""b"", ""kind"": ""point"" },
                { ""name"": ""sky"", ""kind"": ""environment"", ""file"": ""Assets/sky.exr"", ""rotations"": [0, 90.5, 360, 0, -10] } ] } }");
            var problems = Problems(s).ToList();
            Assert.That(problems.Select(p => p.Field), Is.EquivalentTo(new[]
            {
                "relighting.conditions[2].rotations[1]", "relighting.conditions[2].rotations[2]", "relighting.conditions[2].rotations[3]", "relighting.conditions[2].rotations[4]",
            }));
            var half = problems.Single(p => p.Field == "relighting.conditions[2].rotations[1]");
            Assert.That(half.Reason, Does.Contain("whole number of degrees from 0 to 359"));
            Assert.That(problems.Single(p => p.Field == "relighting.conditions[2].rotations[3]").Reason, Does.Contain("repeats rotations[0]"));
            Assert.That(problems.Single(p => p.Field == "relighting.conditions[2].rotations[4]").Fix, Does.Contain("350"));
        }

        [Test]
        public void NamesFilesAndVectorsAreChecked()
        {
            var s = Read(@"{ ""relighting"": { ""conditions"": [
                { ""name"": ""Sunset"", ""kind"": ""environment"" },
                { ""name"": ""olat"", ""kind"": ""point"", ""colour"": [1, -1, 1] },
                { ""name"": ""olat"", ""kind"": ""spot"", ""direction"": [0, 0, 0], ""spotAngle"": 180 } ] } }");
            var problems = Problems(s).ToList();
            Assert.That(problems.Select(p => p.Field), Is.EquivalentTo(new[]
            {
                "relighting.conditions[0].name", "relighting.conditions[0].file", "relighting.conditions[1].colour",
                "relighting.conditions[2].name", "relighting.conditions[2].direction", "relighting.conditions[2].spotAngle",
            }));
            Assert.That(problems.Single(p => p.Field == "relighting.conditions[0].name").Fix, Does.Contain("lowercase"));
            Assert.That(problems.Single(p => p.Field == "relighting.conditions[0].file").Reason, Does.Contain("required for an environment"));
            Assert.That(problems.Single(p => p.Field == "relighting.conditions[2].name").Reason, Does.Contain("also the name of relighting.conditions[1]"));
        }

        [Test]
        public void AnEmptyListAndMotionBlurAreRefused()
        {
            Assert.That(Problems(Read(@"{ ""relighting"": { } }")).Select(p => p.Field), Is.EqualTo(new[] { "relighting.conditions" }));
            var s = Read(Contract);
            s.MotionBlur = new MotionBlurSettings { Enabled = true };
            Assert.That(Problems(s).Select(p => p.Field), Has.Member("relighting"));
        }

        [Test]
        public void EveryViewOfEverySplitWritesOnePngPerKeyAndTheExrWhereHdrApplies()
        {
            var s = Read(Contract);
            s.Hdr.On = true;
            s.Hdr.Val = false;
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Val), Has.Member(DatasetFileKind.RelitPng).And.No.Member(DatasetFileKind.RelitHdrExr));
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Test), Has.Member(DatasetFileKind.RelitHdrExr));
            Assert.That(DatasetLayout.RelitRelativePath(DatasetSplit.Test, 7, "sunset_090", false), Is.EqualTo("test/r_7_light_sunset_090.png"));
            Assert.That(DatasetLayout.RelitRelativePath(DatasetSplit.Test, 7, "olat-00", true), Is.EqualTo("test/r_7_light_olat-00_hdr.exr"));
            Assert.That(RelightingKeys.HdrPathOf("./test/r_7_light_olat-00.png"), Is.EqualTo("./test/r_7_light_olat-00_hdr.exr"));
        }
    }
}
