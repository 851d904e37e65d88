using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Advice the tool prints and examples the pages show, pasted as a user pastes them into the bundled sample config
    /// (issue 33, "Wrong advice"), and the bundled sample configs planned as the README plans the first.
    /// </summary>
    [TestFixture]
    public class PastedAdviceTests
    {
        Scratch _scratch;

        [SetUp]
        public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        static string SampleFolder => Path.Combine(InstalledTool.RepositoryRoot, "Assets", "Samples", "NeRFSample");

        /// <summary>The sample config with <paramref name="member"/> pasted as its first member, as text.</summary>
        string SampleWith(string member)
        {
            var text = File.ReadAllText(Path.Combine(SampleFolder, "nerf-sample.json"));
            var brace = text.IndexOf('{');
            return _scratch.WriteText("pasted.json", text.Substring(0, brace + 1) + "\n" + member + "," + text.Substring(brace + 1));
        }

        /// <summary>The first ```json block of a user page.</summary>
        static string FirstJsonBlock(string page)
        {
            var text = File.ReadAllText(Path.Combine(InstalledTool.RepositoryRoot, "Documentation~", page)).Replace("\r\n", "\n");
            var match = Regex.Match(text, "```json\n(.*?)```", RegexOptions.Singleline);
            Assert.That(match.Success, Is.True, page + " has no json block");
            return match.Groups[1].Value.Trim();
        }

        [Test]
        public void TheGaussianGroupingErrorsLabelsAdvice_PastedIntoTheSampleConfig_Plans()
        {
            var dataset = RenderedDataset.Create(_scratch, "ds");
            var refused = ToolRun.Of("convert", dataset, "--to", "gaussian-grouping");
            Assert.That(refused.ExitCode, Is.EqualTo(1), refused.ToString());
            var advice = Regex.Match(refused.Err, "\"labels\": \\{[^}]*\\}");
            Assert.That(advice.Success, Is.True, refused.ToString());

            var config = SampleWith(advice.Value);
            var read = DatasetSettingsJson.ReadFile(config);
            Assert.That(read.Warnings, Is.Empty, "no unknown key");
            Assert.That(read.Settings.Labels.Enabled, Is.True);
            var plan = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("planned"));
            Assert.That(plan.ExitCode, Is.EqualTo(0), plan.ToString());
            Assert.That(plan.Err, Does.Not.Contain("warning:").And.Not.Contain("error:"));
        }

        [Test]
        public void TheMotionBlurPagesFirstExample_PastedIntoTheSampleConfig_PlansWithoutAWarning()
        {
            var config = SampleWith(FirstJsonBlock("motion-blur.md"));
            Assert.That(DatasetSettingsJson.ReadFile(config).Settings.MotionBlur.Enabled, Is.True);
            var plan = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("planned"));
            Assert.That(plan.ExitCode, Is.EqualTo(0), plan.ToString());
            Assert.That(plan.Err, Is.Empty, plan.ToString());
        }

        [Test]
        public void TheFlowPagesExample_PastedIntoTheSampleConfig_PlansWithoutAWarning()
        {
            var config = SampleWith(FirstJsonBlock("flow.md"));
            var read = DatasetSettingsJson.ReadFile(config);
            Assert.That(read.Warnings, Is.Empty, "no unknown key");
            Assert.That(read.Settings.Flow.Enabled, Is.True);
            Assert.That(read.Settings.Flow.TrackQueryFrames, Is.EqualTo(new[] { 0 }));
            Assert.That(SettingsValidator.Validate(read.Settings).Where(p => p.Field.StartsWith("flow") || p.Field == "geometryPack"), Is.Empty);
            var plan = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("planned"));
            Assert.That(plan.ExitCode, Is.EqualTo(0), plan.ToString());
            Assert.That(plan.Err, Is.Empty, plan.ToString());
        }

        /// <summary>
        /// Path blur with the defaults on the sample config: its random val split's views are far apart, so no
        /// sub-frame count covers the blur; the advice names the split and a shutter that 256 sub-frames cover, never
        /// more sub-frames than there can be (issue 33: "Raise subFrames to 722" while the maximum is 256).
        /// </summary>
        [Test]
        public void PathBlurOnTheSamplesRandomValSplit_AdvisesWhatCanBeDone()
        {
            var config = SampleWith("\"motionBlur\": { \"enabled\": true, \"camera\": \"path\", \"shutter\": 0.5, \"subFrames\": 16 }");
            var plan = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("planned"));
            Assert.That(plan.ExitCode, Is.EqualTo(0), plan.ToString());
            var warnings = plan.Err.TrimEnd('\n').Split('\n').Where(l => l.StartsWith("warning: motionBlur.subFrames")).ToList();
            Assert.That(warnings, Is.Not.Empty, plan.ToString());
            foreach (Match raise in Regex.Matches(plan.Err, "Raise motionBlur.subFrames to (\\d+)"))
                Assert.That(int.Parse(raise.Groups[1].Value), Is.LessThanOrEqualTo(256), plan.ToString());
            var val = warnings.Single(w => w.Contains(" val views "));
            Assert.That(val, Does.Contain("the val split's random formation").And.Contain("Give splits.val a formation whose views are neighbours"));
            var shutter = double.Parse(Regex.Match(val, "set motionBlur.shutter to ([0-9.]+) or less with subFrames 256").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
            Assert.That(shutter, Is.GreaterThan(0).And.LessThan(0.5));

            // Following the advice: that shutter with 256 sub-frames leaves no warning about the val split.
            var followed = _scratch.WriteText("followed.json", File.ReadAllText(config).Replace("\"shutter\": 0.5, \"subFrames\": 16",
                "\"shutter\": " + shutter.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", \"subFrames\": 256"));
            var again = ToolRun.Of("plan", "--config", followed, "--out", _scratch.PathOf("followed"));
            Assert.That(again.ExitCode, Is.EqualTo(0), again.ToString());
            Assert.That(again.Err, Does.Not.Contain(" val views "), again.ToString());
        }

        /// <summary>Every bundled sample config plans headless without a warning; the dynamic ones (<c>"end": "clip"</c>) with a note on the assumed clip.</summary>
        [TestCase("nerf-sample.json", false)]
        [TestCase("nerf-sample-dynamic.json", true)]
        [TestCase("nerf-sample-multiview.json", true)]
        public void EverySampleConfigPlansHeadless(string name, bool clip)
        {
            var output = _scratch.PathOf(Path.GetFileNameWithoutExtension(name));
            var run = ToolRun.Of("plan", "--config", Path.Combine(SampleFolder, name), "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Err, Does.Not.Contain("warning:").And.Not.Contain("error:"), run.ToString());
            if (clip)
            {
                Assert.That(run.Err, Does.StartWith("note: time.end = \"clip\": the clip's length is known only in Unity"));
                Assert.That(run.Out, Does.Contain(" steps from 0 s to 1 s"));
            }
            else Assert.That(run.Err, Is.Empty);
            Assert.That(ToolRun.Of("validate", output).ExitCode, Is.EqualTo(0));
        }

        /// <summary>With time.fps the steps follow from the clip's length, which the tool cannot know: still refused, naming the key.</summary>
        [Test]
        public void AClipEndWithAFrameRateIsStillRefusedHeadless()
        {
            var text = File.ReadAllText(Path.Combine(SampleFolder, "nerf-sample-dynamic.json"));
            var config = _scratch.WriteText("fps.json", Regex.Replace(text, "\"fps\": 0", "\"fps\": 24"));
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("fps"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: " + config + "(").And.Contain("): time.end = \"clip\": needs the length"));
        }
    }
}
