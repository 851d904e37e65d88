using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The "flow" section: its JSON round trip, the on/off convention, and every refusal naming its key.</summary>
    public class FlowSettingsTests
    {
        static DatasetSettings Dynamic()
        {
            var s = new DatasetSettings();
            s.Train.Count = 10;
            s.Time.Mode = TimeMode.Monocular;
            s.Time.Steps = 10;
            s.GeometryPackEveryStep = true;
            s.Flow.On = true;
            return s;
        }

        static string[] FlowProblems(DatasetSettings s) =>
            FlowSettingsValidator.Validate(s).Select(p => p.Field + ": " + p.Reason + " " + p.Fix).ToArray();

        [Test]
        public void TheSectionRoundTripsAndIsWrittenOnlyWhenOn()
        {
            var off = DatasetSettingsJson.Write(new DatasetSettings());
            Assert.That(off, Does.Not.Contain("\"flow\""));
            var s = Dynamic();
            s.Flow.Backward = false;
            s.Flow.Spans = new[] { 1, 3 };
            s.Flow.SceneFlow = false;
            s.Flow.TrackQueryFrames = new[] { 0, 5 };
            s.Flow.TrackStride = 4;
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text, Does.Contain("\"flow\""));
            var back = DatasetSettingsJson.Read(text).Settings.Flow;
            Assert.That(back.Enabled, Is.True);
            Assert.That((back.Forward, back.Backward, back.SceneFlow, back.TrackStride), Is.EqualTo((true, false, false, 4)));
            Assert.That(back.Spans, Is.EqualTo(new[] { 1, 3 }));
            Assert.That(back.TrackQueryFrames, Is.EqualTo(new[] { 0, 5 }));
            Assert.That(DatasetSettingsJson.Write(DatasetSettingsJson.Read(text).Settings), Is.EqualTo(text));
        }

        [Test]
        public void GivingTheSectionTurnsItOnAndEnabledFalseTurnsItOff()
        {
            var on = DatasetSettingsJson.Read("{ \"flow\": {} }").Settings.Flow;
            Assert.That(on.Enabled, Is.True);
            Assert.That((on.Forward, on.Backward, on.SceneFlow, on.TrackStride), Is.EqualTo((true, true, true, 8)));
            Assert.That(on.Spans, Is.EqualTo(new[] { 1 }));
            Assert.That(on.TrackQueryFrames, Is.Empty);
            Assert.That(DatasetSettingsJson.Read("{ \"flow\": { \"enabled\": false, \"spans\": [2] } }").Settings.Flow.Enabled, Is.False);
            Assert.That(DatasetSettingsJson.Read("{}").Settings.Flow.Enabled, Is.False);
        }

        [Test]
        public void MalformedValuesAreRefusedNamingTheKey()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"flow\": { \"spans\": 1 } }"));
            Assert.That(e.Message, Does.Contain("flow.spans").And.Contain("list"));
            e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"flow\": { \"tracks\": { \"stride\": \"8\" } } }"));
            Assert.That(e.Message, Does.Contain("flow.tracks.stride"));
            var warnings = DatasetSettingsJson.Read("{ \"flow\": { \"forwards\": true } }").Warnings;
            Assert.That(warnings.Select(w => w.Field), Does.Contain("flow.forwards"), "an unknown key is named");
        }

        [Test]
        public void AValidSectionHasNoProblems()
        {
            var s = Dynamic();
            s.Flow.Spans = new[] { 1, 9 };
            s.Flow.TrackQueryFrames = new[] { 0, 9 };
            Assert.That(FlowProblems(s), Is.Empty);
            Assert.That(SettingsValidator.Validate(s).Where(p => p.Field.StartsWith("flow")), Is.Empty);
        }

        [Test]
        public void AStaticCaptureIsRefused()
        {
            var s = Dynamic();
            s.Time.Mode = TimeMode.Static;
            Assert.That(FlowProblems(s), Has.Some.StartsWith("flow: needs a dynamic capture").And.Some.Contains("time.mode"));
            Assert.That(SettingsValidator.Validate(s).Select(p => p.Field), Does.Contain("flow"), "wired into the settings validator");
        }

        [Test]
        public void AGeometryPackNotAtEveryStepIsRefused()
        {
            var s = Dynamic();
            s.GeometryPackEveryStep = false;
            Assert.That(FlowProblems(s), Has.Some.StartsWith("geometryPack: is not \"everyStep\"").And.Some.Contains("\"geometryPack\": \"everyStep\""));
            s.GeometryPack = false;
            s.GeometryPackEveryStep = true;
            Assert.That(FlowProblems(s), Has.Some.StartsWith("geometryPack: is not \"everyStep\""));
        }

        [Test]
        public void ALensIsRefused()
        {
            var s = Dynamic();
            s.Lens.Model = "opencv";
            Assert.That(s.Lens.Enabled, Is.True);
            Assert.That(FlowProblems(s), Has.Some.StartsWith("lens: is not carried by flow"));
        }

        [TestCase(new[] { 0 }, "flow.spans[0]: is below 1")]
        [TestCase(new[] { 1, -2 }, "flow.spans[1]: is below 1")]
        [TestCase(new[] { 10 }, "flow.spans[0]: is not below the 10 time steps")]
        [TestCase(new[] { 1, 1 }, "flow.spans[1]: is given twice")]
        [TestCase(new int[0], "flow.spans: is empty")]
        public void SpansAtLeastOneAndBelowTheStepsElseRefused(int[] spans, string expected)
        {
            var s = Dynamic();
            s.Flow.Spans = spans;
            Assert.That(FlowProblems(s), Has.Some.StartsWith(expected));
        }

        [TestCase(new[] { -1 }, "flow.tracks.queryFrames[0]: is not a frame of the videos (0 to 9")]
        [TestCase(new[] { 0, 10 }, "flow.tracks.queryFrames[1]: is not a frame of the videos (0 to 9")]
        [TestCase(new[] { 3, 3 }, "flow.tracks.queryFrames[1]: is given twice")]
        public void QueryFramesAmongTheStepsElseRefused(int[] frames, string expected)
        {
            var s = Dynamic();
            s.Flow.TrackQueryFrames = frames;
            Assert.That(FlowProblems(s), Has.Some.StartsWith(expected));
        }

        [Test]
        public void AStrideBelowOneIsRefused()
        {
            var s = Dynamic();
            s.Flow.TrackStride = 0;
            Assert.That(FlowProblems(s), Has.Some.StartsWith("flow.tracks.stride: is below 1"));
        }

        [Test]
        public void NothingToWriteIsRefused()
        {
            var s = Dynamic();
            s.Flow.Forward = s.Flow.Backward = false;
            Assert.That(FlowProblems(s), Has.Some.StartsWith("flow.forward: and flow.backward are both false"));
            s.Flow.TrackQueryFrames = new[] { 0 };
            Assert.That(FlowProblems(s), Is.Empty, "tracks alone are something to write");
        }

        [Test]
        public void TheStepCountComesFromTheFrameRateWhenGiven()
        {
            var s = Dynamic();
            s.Time.Steps = 0;
            s.Time.Mode = TimeMode.MultiView;
            s.Time.StartSeconds = 0;
            s.Time.EndSeconds = 1;
            s.Time.Fps = 4;
            Assert.That(FlowSettingsValidator.KnownSteps(s), Is.EqualTo(5), "0, 0.25, 0.5, 0.75, 1 s");
            s.Flow.Spans = new[] { 5 };
            Assert.That(FlowProblems(s), Has.Some.StartsWith("flow.spans[0]: is not below the 5 time steps"));
            s.Time.EndAtClipLength = true;
            Assert.That(FlowSettingsValidator.KnownSteps(s), Is.Null, "the clip's length decides");
        }
    }
}
