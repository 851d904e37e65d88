using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class TimeSettingsTests
    {
        [Test]
        public void StaticSettingsWriteNoTimeSection()
        {
            Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("\"time\""));
        }

        [Test]
        public void TimeSectionRoundTrips()
        {
            var s = new DatasetSettings();
            s.Time.Mode = TimeMode.MultiView;
            s.Time.Sources = TimeSources.Timeline | TimeSources.Particles;
            s.Time.StartSeconds = 0.25;
            s.Time.EndAtClipLength = true;
            s.Time.Fps = 24;
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text.Replace("\r", ""), Does.Contain("\"sources\": [\n      \"timeline\",\n      \"particles\"\n    ]"));
            Assert.That(text, Does.Contain("\"end\": \"clip\""));
            var read = DatasetSettingsJson.Read(text);
            Assert.That(read.Warnings, Is.Empty);
            var t = read.Settings.Time;
            Assert.That(t.Mode, Is.EqualTo(TimeMode.MultiView));
            Assert.That(t.Sources, Is.EqualTo(TimeSources.Timeline | TimeSources.Particles));
            Assert.That(t.StartSeconds, Is.EqualTo(0.25));
            Assert.That(t.EndAtClipLength, Is.True);
            Assert.That(t.Fps, Is.EqualTo(24));
            Assert.That(DatasetSettingsJson.Write(read.Settings), Is.EqualTo(text));
        }

        [Test]
        public void ReadsAHandWrittenSection()
        {
            var read = DatasetSettingsJson.Read("{ \"time\": { \"mode\": \"monocular\", \"end\": 3.5, \"sources\": [\"animator\"], \"colour\": 1 } }");
            Assert.That(read.Settings.Time.Mode, Is.EqualTo(TimeMode.Monocular));
            Assert.That(read.Settings.Time.EndSeconds, Is.EqualTo(3.5));
            Assert.That(read.Settings.Time.Sources, Is.EqualTo(TimeSources.Animator));
            Assert.That(read.Warnings.Select(w => w.Field), Is.EqualTo(new[] { "time.colour" }));
        }

        [Test]
        public void BadValuesNameTheirPlace()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\n \"time\": { \"mode\": \"4d\" } }"));
            Assert.That(e.Message, Does.Contain("time.mode"));
            Assert.That(e.Line, Is.EqualTo(2));
            e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"time\": { \"sources\": [\"physics\"] } }"));
            Assert.That(e.Message, Does.Contain("time.sources[0]"));
        }

        static string[] Fields(DatasetSettings s) => SettingsValidator.Validate(s).Select(p => p.Field).ToArray();

        [Test]
        public void ValidationNamesEachTimeField()
        {
            var s = new DatasetSettings();
            s.Time.Mode = TimeMode.MultiView;
            Assert.That(Fields(s), Is.EqualTo(new[] { "time.steps" }), "multi-view needs steps or fps");
            s.Time.Steps = 5;
            Assert.That(Fields(s), Is.Empty);
            s.Time.EndSeconds = 0;
            Assert.That(Fields(s), Is.EqualTo(new[] { "time.end" }));
            s.Time.EndSeconds = 2;
            s.Time.Fps = 30;
            Assert.That(Fields(s), Is.EqualTo(new[] { "time.fps" }), "steps and fps together");
            s.Time.Fps = 0;
            s.Time.Sources = TimeSources.None;
            s.Time.StartSeconds = double.NaN;
            Assert.That(Fields(s), Is.EqualTo(new[] { "time.sources", "time.start" }));
        }

        [Test]
        public void MonocularStepsMustMatchTheTrainViews()
        {
            var s = new DatasetSettings();
            s.Time.Mode = TimeMode.Monocular;
            Assert.That(Fields(s), Is.Empty, "steps 0: the 100 train views are the steps");
            s.Time.Steps = 50;
            var problem = SettingsValidator.Validate(s).Single();
            Assert.That(problem.Field, Is.EqualTo("time.steps"));
            Assert.That(problem.Fix, Does.Contain("splits.train.count to 50"));
            s.Time.Steps = 0;
            s.Train.Count = 1;
            Assert.That(Fields(s), Is.EqualTo(new[] { "splits.train.count" }));
        }

        [Test]
        public void StaticModeIgnoresTheRestOfTheSection()
        {
            var s = new DatasetSettings();
            s.Time.EndSeconds = -1;
            s.Time.Sources = TimeSources.None;
            Assert.That(Fields(s), Is.Empty);
        }

        [Test]
        public void CloneCopiesTheTimeSection()
        {
            var s = new DatasetSettings();
            var copy = s.Clone();
            copy.Time.Mode = TimeMode.Monocular;
            Assert.That(s.Time.Mode, Is.EqualTo(TimeMode.Static));
        }
    }
}
