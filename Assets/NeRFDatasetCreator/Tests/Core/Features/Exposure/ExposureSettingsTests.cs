using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ExposureSettingsTests
    {
        [Test]
        public void ConfigRoundTripsAndOffKeepsTheOldShape()
        {
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("exposure"));
            var s = new DatasetSettings();
            s.Exposure.Mode = ExposureMode.Random;
            s.Exposure.Test = true;
            s.Exposure.EvMin = -2;
            s.Exposure.EvMax = 0.75;
            s.Exposure.GainMin = 0.9;
            s.Exposure.GainMax = 1.1;
            s.Exposure.WriteClean = false;
            var back = DatasetSettingsJson.Read(DatasetSettingsJson.Write(s)).Settings.Exposure;
            Assert.That(back.Mode, Is.EqualTo(ExposureMode.Random));
            Assert.That((back.Train, back.Val, back.Test), Is.EqualTo((true, false, true)));
            Assert.That((back.EvMin, back.EvMax, back.GainMin, back.GainMax), Is.EqualTo((-2.0, 0.75, 0.9, 1.1)));
            Assert.That(back.WriteClean, Is.False);

            s.Exposure.Mode = ExposureMode.List;
            s.Exposure.Values = new List<ViewExposure> { new ViewExposure(0.5, 1.1, 1, 0.95) };
            var list = DatasetSettingsJson.Read(DatasetSettingsJson.Write(s)).Settings.Exposure;
            Assert.That(list.Values, Is.EqualTo(s.Exposure.Values));
        }

        [Test]
        public void GivingTheSectionTurnsItOn()
        {
            var read = DatasetSettingsJson.Read("{ \"exposure\": { \"evRange\": [-1, 1], \"splits\": [\"train\", \"val\"] } }");
            Assert.That(read.Settings.Exposure.Mode, Is.EqualTo(ExposureMode.Random));
            Assert.That(read.Settings.Exposure.Val, Is.True);
            Assert.That(read.Warnings, Is.Empty);
        }

        [Test]
        public void WrongTypesNameTheirKey()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"exposure\": { \"evRange\": 1 } }"));
            Assert.That(e.Message, Does.Contain("exposure.evRange"));
            e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"exposure\": { \"splits\": [\"tran\"] } }"));
            Assert.That(e.Message, Does.Contain("exposure.splits[0]"));
            e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"exposure\": { \"mode\": \"list\", \"values\": [ { \"whiteBalance\": [1, 1] } ] } }"));
            Assert.That(e.Message, Does.Contain("exposure.values[0].whiteBalance"));
        }

        [Test]
        public void OutOfRangeValuesNameTheirKey()
        {
            var s = new DatasetSettings();
            s.Exposure.Mode = ExposureMode.Random;
            s.Exposure.EvMin = 1;
            s.Exposure.EvMax = -1;
            s.Exposure.GainMin = 0;
            Assert.That(Fields(s), Is.EquivalentTo(new[] { "exposure.evRange", "exposure.gainRange[0]" }));
            s.Exposure.EvMin = -1;
            s.Exposure.GainMin = 0.8;
            s.Exposure.Train = false;
            Assert.That(Fields(s), Is.EquivalentTo(new[] { "exposure.splits" }));
            s.Exposure.Train = true;
            s.Exposure.Mode = ExposureMode.List;
            Assert.That(Fields(s), Is.EquivalentTo(new[] { "exposure.values" }));
            s.Exposure.Values.Add(new ViewExposure(11, 1, 1, 1));
            s.Exposure.Values.Add(new ViewExposure(0, 1, 20, 1));
            Assert.That(Fields(s), Is.EquivalentTo(new[] { "exposure.values[0].ev", "exposure.values[1].whiteBalance[1]" }));
            s.Exposure.Mode = ExposureMode.Off;
            Assert.That(Fields(s), Is.Empty, "off: nothing is checked");
        }

        [Test]
        public void WindowShowsEveryExposureProblemInTheOutputsStep()
        {
            var s = new DatasetSettings();
            s.Exposure.Mode = ExposureMode.Random;
            s.Exposure.EvMax = 30;
            s.Exposure.Train = false;
            var problems = SettingsValidator.Validate(s);
            var fieldProblems = new FieldProblems(problems, null);
            Assert.That(problems.Select(p => p.Field), Has.Member("exposure.evRange[1]"));
            Assert.That(fieldProblems.NotCoveredBy(WindowFields.All(s)), Is.Empty, "a problem without a control in the window");
            Assert.That(WindowFields.StepOf("exposure.evRange[1]"), Is.EqualTo(WindowStep.Outputs));
            Assert.That(fieldProblems.FirstIncompleteStep(), Is.EqualTo(WindowStep.Outputs));
        }

        static IEnumerable<string> Fields(DatasetSettings s) => SettingsValidator.Validate(s).Where(p => p.Field.StartsWith("exposure")).Select(p => p.Field);
    }
}
