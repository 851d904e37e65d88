using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class LabelSettingsTests
    {
        [Test]
        public void SettingsWithoutLabelsWriteNoLabelsSectionAndPlanNoIdMaps()
        {
            var s = new DatasetSettings();
            Assert.That(DatasetSettingsJson.Write(s), Does.Not.Contain("\"labels\""));
            Assert.That(DatasetLayout.FileKinds(s.Train, s.Labels), Is.EqualTo(new[] { DatasetFileKind.Color }));
        }

        [Test]
        public void TheLabelsSectionRoundTripsAndTurnsLabelsOn()
        {
            var s = new DatasetSettings();
            s.Labels = new LabelSettings
            {
                Enabled = true, Instances = InstanceRule.TargetChild, ClassFrom = ClassSource.Name, OtherClass = "other",
                Classes = { new ClassRule("Car*", "car"), new ClassRule("Tree ?", "vegetation") },
            };
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text.Replace("\r", ""), Does.Contain("\"labels\": {\n    \"instances\": \"child\",\n    \"classFrom\": \"name\",\n    \"classes\": [\n      {\n        \"match\": \"Car*\",\n        \"class\": \"car\"\n      },"));
            var read = DatasetSettingsJson.Read(text);
            Assert.That(read.Warnings, Is.Empty);
            var l = read.Settings.Labels;
            Assert.That(l.Enabled, Is.True);
            Assert.That(l.Instances, Is.EqualTo(InstanceRule.TargetChild));
            Assert.That(l.ClassFrom, Is.EqualTo(ClassSource.Name));
            Assert.That(l.Classes.Select(r => r.Match + "=" + r.Class), Is.EqualTo(new[] { "Car*=car", "Tree ?=vegetation" }));
            Assert.That(l.OtherClass, Is.EqualTo("other"));
            Assert.That(DatasetSettingsJson.Write(read.Settings), Is.EqualTo(text));
            Assert.That(SettingsValidator.Validate(read.Settings), Is.Empty);
            // Every split writes both maps, after the split's own files.
            Assert.That(DatasetLayout.FileKinds(read.Settings.Test, read.Settings.Labels).Skip(1), Is.EqualTo(new[] { DatasetFileKind.InstancePng, DatasetFileKind.SemanticPng }));
        }

        [Test]
        public void AnEmptyLabelsObjectTurnsLabelsOnWithTheDefaults()
        {
            var read = DatasetSettingsJson.Read("{ \"labels\": {} }");
            Assert.That(read.Settings.Labels.Enabled, Is.True);
            Assert.That(read.Settings.Labels.Instances, Is.EqualTo(InstanceRule.PrefabInstance));
            Assert.That(read.Settings.Labels.ClassFrom, Is.EqualTo(ClassSource.Tag));
            Assert.That(SettingsValidator.Validate(read.Settings), Is.Empty);
        }

        [Test]
        public void BadValuesNameTheirKey()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\n \"labels\": { \"instances\": \"mesh\" } }"));
            Assert.That(e.Message, Does.Contain("labels.instances").And.Contain("\"renderer\", \"prefab\", \"child\""));
            Assert.That(e.Line, Is.EqualTo(2));
            e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"labels\": { \"classFrom\": \"tags\" } }"));
            Assert.That(e.Message, Does.Contain("labels.classFrom").And.Contain("tag"));
            e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"labels\": { \"classes\": { \"Car\": \"car\" } } }"));
            Assert.That(e.Message, Does.Contain("labels.classes").And.Contain("must be a list"));
            var read = DatasetSettingsJson.Read("{ \"labels\": { \"classes\": [ { \"match\": \"Car\", \"name\": \"car\" } ] } }");
            Assert.That(read.Warnings.Select(w => w.Field), Is.EqualTo(new[] { "labels.classes[0].name" }));
        }

        static string[] Fields(DatasetSettings s) => SettingsValidator.Validate(s).Select(p => p.Field).ToArray();

        [Test]
        public void ValidationNamesEachLabelsField()
        {
            var s = new DatasetSettings();
            s.Labels.Enabled = true;
            s.Labels.ClassFrom = ClassSource.Name;
            Assert.That(Fields(s), Is.EqualTo(new[] { "labels.classes" }), "name patterns need rules");
            s.Labels.Classes.Add(new ClassRule("Car*", "car"));
            Assert.That(Fields(s), Is.Empty);
            s.Labels.Classes.Add(new ClassRule("", "tree"));
            s.Labels.Classes.Add(new ClassRule("Car*", " "));
            Assert.That(Fields(s), Is.EqualTo(new[] { "labels.classes[1].match", "labels.classes[2].match", "labels.classes[2].class" }));
            s.Labels.Classes.RemoveRange(1, 2);
            s.Labels.OtherClass = "  ";
            s.Labels.Instances = (InstanceRule)7;
            Assert.That(Fields(s), Is.EqualTo(new[] { "labels.instances", "labels.otherClass" }));
            s.Labels.Enabled = false;
            Assert.That(Fields(s), Is.Empty, "nothing is checked while labels are off");
        }

        [Test]
        public void CloneCopiesTheRules()
        {
            var s = new DatasetSettings();
            s.Labels.Classes.Add(new ClassRule("Car", "car"));
            var copy = s.Clone();
            copy.Labels.Classes[0].Class = "vehicle";
            copy.Labels.Classes.Add(new ClassRule("Bus", "bus"));
            Assert.That(s.Labels.Classes.Single().Class, Is.EqualTo("car"));
        }

        [TestCase("Car*", "Car (3)", true)]
        [TestCase("Car*", "Car", true)]
        [TestCase("Car*", "Red Car", false)]
        [TestCase("*Car", "Red Car", true)]
        [TestCase("C?r", "Car", true)]
        [TestCase("C?r", "Cr", false)]
        [TestCase("*/Props/*.prefab", "Assets/Props/Car.prefab", true)]
        [TestCase("a*b*c", "aXXbYYc", true)]
        [TestCase("a*b*c", "aXXbYY", false)]
        [TestCase("car", "Car", false)]
        [TestCase("*", "", true)]
        [TestCase("", "", true)]
        [TestCase("", "x", false)]
        public void PatternsMatchTheWholeNameWithStarAndQuestionMark(string pattern, string text, bool matches)
        {
            Assert.That(LabelPattern.Matches(pattern, text), Is.EqualTo(matches));
        }
    }
}
