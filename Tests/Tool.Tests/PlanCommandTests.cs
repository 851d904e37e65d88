using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    [TestFixture]
    public class PlanCommandTests
    {
        const string SmallConfig =
            "{ \"schemaVersion\": 1, \"name\": \"lego\", \"seed\": 5,\n" +
            "  \"splits\": { \"train\": { \"count\": 12 }, \"val\": { \"count\": 4 }, \"test\": { \"count\": 6, \"depth\": \"png\", \"mask\": true } } }";

        Scratch _scratch;

        [SetUp]
        public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        [Test]
        public void PlanWritesTheJsonFilesAndARigPreviewButNoImages()
        {
            var config = _scratch.WriteText("lego.json", SmallConfig);
            var output = _scratch.PathOf("out", "lego");
            var run = ToolRun.Of("plan", "--config", config, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("planned 12 train, 4 val, 6 test views at distance 4"));
            Assert.That(Directory.GetFiles(output).Select(Path.GetFileName).OrderBy(n => n, System.StringComparer.Ordinal), Is.EqualTo(new[]
            {
                "dataset_config.json", "eval_protocol.json", "rig_preview.ply", "rig_preview.png", "transforms_test.json", "transforms_train.json", "transforms_val.json",
            }));
            Assert.That(Directory.GetDirectories(output), Is.Empty, "no image folders");
            Assert.That(Directory.GetDirectories(_scratch.PathOf("out")), Is.EqualTo(new[] { output }), "no partial folder left beside it");
            var test = JObject.Parse(File.ReadAllText(Path.Combine(output, "transforms_test.json")));
            Assert.That(((JArray)test["frames"]).Count, Is.EqualTo(6));
            Assert.That((string)test["frames"][5]["depth_path"], Is.EqualTo("./test/r_5_depth_0000.png"));
            var config_ = JObject.Parse(File.ReadAllText(Path.Combine(output, "dataset_config.json")));
            Assert.That((bool)config_["imagesRendered"], Is.False);
            Assert.That((long)config_["settings"]["seed"], Is.EqualTo(5));
            var bytes = File.ReadAllBytes(Path.Combine(output, "rig_preview.ply"));
            var ply = System.Text.Encoding.ASCII.GetString(bytes, 0, 600);
            Assert.That(ply, Does.StartWith("ply\nformat binary_little_endian 1.0\n"));
            Assert.That(ply, Does.Contain("\nelement vertex " + (1 + 5 * 22) + "\n").And.Contain("\nelement edge " + 8 * 22 + "\n"));
            var header = ply.IndexOf("end_header\n", System.StringComparison.Ordinal) + "end_header\n".Length;
            Assert.That(bytes.Length, Is.EqualTo(header + (1 + 5 * 22) * 15 + 8 * 22 * 11), "15 bytes per vertex, 11 per edge");
        }

        /// <summary>
        /// A wrong type and two values out of range: all three in one run, each with its line and column (issue 33:
        /// "config errors come in two rounds and range errors have no line").
        /// </summary>
        [Test]
        public void EveryConfigErrorIsReportedAtOnceWithItsLine()
        {
            var config = _scratch.WriteText("bad.json",
                "{\n" +
                "  \"width\": \"wide\",\n" +
                "  \"distance\": -3,\n" +
                "  \"splits\": {\n" +
                "    \"train\": { \"count\": 0 },\n" +
                "    \"val\": { \"count\": 2 }\n" +
                "  }\n" +
                "}\n");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("bad"));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            var errors = run.Err.TrimEnd('\n').Split('\n');
            // Line and column of each value, as the JSON reader counts them (the column after the value).
            Assert.That(errors, Has.Length.EqualTo(3), run.ToString());
            Assert.That(errors[0], Is.EqualTo("error: " + config + "(2,17): width: must be a whole number, not \"wide\"."));
            Assert.That(errors[1], Does.StartWith("error: " + config + "(3,16): distance = -3: must be above 0."));
            Assert.That(errors[2], Does.StartWith("error: " + config + "(5,25): splits.train.count = 0: leaves the train split empty"));
            Assert.That(Directory.Exists(_scratch.PathOf("bad")), Is.False);
        }

        [Test]
        public void PlanThenValidateSucceedsOnItsOwnOutput()
        {
            var config = _scratch.WriteText("lego.json", SmallConfig);
            var output = _scratch.PathOf("lego");
            Assert.That(ToolRun.Of("plan", "--config", config, "--out", output).ExitCode, Is.EqualTo(0));
            var run = ToolRun.Of("validate", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("train 12, val 4, test 6 frames"));
            Assert.That(run.Out, Does.Contain("warning: dataset_config.json: says the images were not rendered"));
            Assert.That(run.Out, Does.EndWith("OK\n"));
        }

        [Test]
        public void PlanIsDeterministic()
        {
            var config = _scratch.WriteText("lego.json", SmallConfig);
            ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("a"));
            ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("b"));
            foreach (var name in new[] { "transforms_train.json", "transforms_val.json", "transforms_test.json", "rig_preview.ply", "rig_preview.png" })
                Assert.That(File.ReadAllBytes(_scratch.PathOf("b", name)), Is.EqualTo(File.ReadAllBytes(_scratch.PathOf("a", name))), name);
        }

        [Test]
        public void AnExistingDatasetIsNotOverwritten()
        {
            var config = _scratch.WriteText("lego.json", SmallConfig);
            var output = _scratch.PathOf("lego");
            Directory.CreateDirectory(output);
            File.WriteAllText(Path.Combine(output, "transforms_train.json"), "precious");
            var run = ToolRun.Of("plan", "--config", config, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Err, Does.Contain("error: overwrite = never"));
            Assert.That(File.ReadAllText(Path.Combine(output, "transforms_train.json")), Is.EqualTo("precious"));
        }

        [Test]
        public void ReplacePolicyReplacesAnExistingDataset()
        {
            var config = _scratch.WriteText("lego.json", SmallConfig.Replace("\"seed\": 5,", "\"seed\": 5, \"overwrite\": \"replace\","));
            var output = _scratch.PathOf("lego");
            Assert.That(ToolRun.Of("plan", "--config", config, "--out", output).ExitCode, Is.EqualTo(0));
            File.WriteAllText(Path.Combine(output, "transforms_train.json"), "old");
            var run = ToolRun.Of("plan", "--config", config, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(File.ReadAllText(Path.Combine(output, "transforms_train.json")), Does.StartWith("{"));
            Assert.That(Directory.GetFileSystemEntries(_scratch.Root).Select(Path.GetFileName), Is.EquivalentTo(new[] { "lego.json", "lego" }), "no working folder left");
        }

        [Test]
        public void ReplaceNeverDeletesAFolderThatOnlyLooksLikeADataset()
        {
            var config = _scratch.WriteText("lego.json", SmallConfig.Replace("\"seed\": 5,", "\"seed\": 5, \"overwrite\": \"replace\","));
            var output = _scratch.PathOf("lego");
            Directory.CreateDirectory(output);
            File.WriteAllText(Path.Combine(output, "transforms_train.json"), "stray");
            File.WriteAllText(Path.Combine(output, "thesis.tex"), "precious");
            var run = ToolRun.Of("plan", "--config", config, "--out", output);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("error: overwrite = replace: would delete " + output));
            Assert.That(File.ReadAllText(Path.Combine(output, "thesis.tex")), Is.EqualTo("precious"));
            Assert.That(File.ReadAllText(Path.Combine(output, "transforms_train.json")), Is.EqualTo("stray"));
        }

        [Test]
        public void MalformedConfigGivesLineAndColumn()
        {
            var config = _scratch.WriteText("bad.json", "{\n  \"width\": 800\n  \"height\": 600\n}");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("o"));
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Err, Does.Contain("bad.json(2,14): a comma is missing after this value"));
            Assert.That(Directory.Exists(_scratch.PathOf("o")), Is.False);
        }

        [Test]
        public void InvalidSettingsListEveryProblem()
        {
            var config = _scratch.WriteText("bad.json", "{ \"width\": 4, \"supersampling\": 9, \"splits\": { \"val\": { \"count\": -1 } } }");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("o"));
            Assert.That(run.ExitCode, Is.EqualTo(2));
            var errors = run.Err.Split('\n').Where(l => l.StartsWith("error: ")).ToList();
            Assert.That(errors, Has.Count.EqualTo(3), run.ToString());
            // Each placed at its value (one line: the columns after 4, 9 and -1).
            Assert.That(run.Err, Does.Contain("error: " + config + "(1,12): width = 4").And.Contain("error: " + config + "(1,32): supersampling = 9")
                .And.Contain("error: " + config + "(1,66): splits.val.count = -1"));
        }

        [Test]
        public void AutoDistanceNeedsUnity()
        {
            var config = _scratch.WriteText("auto.json", "{ \"distance\": \"auto\" }");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("o"));
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Err, Does.Contain("error: " + config + "(1,20): distance = \"auto\": needs the target's bounds"));
        }

        [Test]
        public void UnknownKeysAreWarnedAboutButDoNotStopThePlan()
        {
            var config = _scratch.WriteText("typo.json", "{ \"widht\": 640 }");
            var run = ToolRun.Of("plan", "--config", config, "--out", _scratch.PathOf("o"));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Err, Does.Contain("warning: widht = 640: is not a known setting"));
        }

        [Test]
        public void MissingConfigFile()
        {
            var run = ToolRun.Of("plan", "--config", _scratch.PathOf("nope.json"), "--out", _scratch.PathOf("o"));
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Err, Does.Contain("nope.json: does not exist"));
        }
    }
}
