using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 22: <c>plan</c> with <c>"overwrite": "replace"</c> deleted a rendered dataset with its colmap/, ngp/ and
    /// nerfstudio exports and exited 0. A plan never replaces a dataset whose images were rendered, and no replace (plan
    /// or capture) deletes an export; each refuses with the reason, before anything is written, at the commit, and in
    /// the recovery of an interrupted replace.
    /// </summary>
    [TestFixture]
    public class ReplaceNeverDeletesRenderingTests
    {
        const string Config = "{ \"width\": 32, \"height\": 24, \"overwrite\": \"replace\", \"splits\": { \"train\": { \"count\": 3 }, \"val\": { \"count\": 2 }, \"test\": { \"count\": 2 } } }";

        Scratch _scratch;
        string _config;
        string _lego;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _config = _scratch.WriteText("lego.json", Config);
            _lego = _scratch.PathOf("lego");
            var run = ToolRun.Of("plan", "--config", _config, "--out", _lego);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
        }

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
            _scratch.Dispose();
        }

        /// <summary>What a capture leaves: an image per frame, and the config saying the images were rendered (when <paramref name="say"/>).</summary>
        void Render(bool say = true)
        {
            var png = TestPng.Encode(32, 24, 8, PngInfo.ColorTypeRgba);
            foreach (var (split, count) in new[] { ("train", 3), ("val", 2), ("test", 2) })
            {
                Directory.CreateDirectory(Path.Combine(_lego, split));
                for (var i = 0; i < count; i++) File.WriteAllBytes(Path.Combine(_lego, split, "r_" + i + ".png"), png);
            }
            if (!say) return;
            var path = Path.Combine(_lego, DatasetLayout.ConfigFileName);
            var config = JObject.Parse(File.ReadAllText(path));
            config["imagesRendered"] = true;
            File.WriteAllText(path, config.ToString());
        }

        void Export()
        {
            foreach (var target in new[] { "nerfstudio", "ngp", "colmap" })
            {
                var run = ToolRun.Of("convert", _lego, "--to", target);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            }
        }

        Dictionary<string, string> Snapshot() =>
            Directory.GetFiles(_lego, "*", SearchOption.AllDirectories)
                .ToDictionary(f => Path.GetRelativePath(_lego, f), f => Convert.ToBase64String(File.ReadAllBytes(f)));

        [Test]
        public void APlanRefusesToReplaceARenderedDatasetWithItsExports()
        {
            Render();
            Export();
            var before = Snapshot();
            Assert.That(before.Keys, Has.Some.StartsWith("colmap").And.Some.StartsWith("ngp").And.Some.EqualTo("transforms.json").And.Some.StartsWith("train"));

            var run = ToolRun.Of("plan", "--config", _config, "--out", _lego);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.StartWith("error: overwrite = replace: would delete " + _lego + ", but " + Path.Combine(_lego, "camera_paths") +
                                                " is an export made with nerf-dataset convert, which a replace would delete and nothing would bring back"), run.ToString());
            Assert.That(Snapshot(), Is.EqualTo(before), "every image and export is still there");
            Assert.That(Interruptions.Entries(_scratch.Root), Is.EqualTo(new[] { "lego", "lego.json" }), "nothing was written beside it");
        }

        [TestCase(true, "its dataset_config.json says its images were rendered (\"imagesRendered\": true)")]
        [TestCase(false, "it holds rendered images (")]
        public void APlanRefusesToReplaceRenderedImages(bool configSaysSo, string reason)
        {
            Render(configSaysSo);
            var before = Snapshot();
            var run = ToolRun.Of("plan", "--config", _config, "--out", _lego);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            Assert.That(run.Err, Does.Contain("would delete " + _lego + ", but " + reason).And.Contain("a plan renders none: replacing it would throw the rendering away"), run.ToString());
            Assert.That(Snapshot(), Is.EqualTo(before));
        }

        [Test]
        public void APlanStillReplacesAPlan()
        {
            var run = ToolRun.Of("plan", "--config", _config, "--out", _lego);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
        }

        [Test]
        public void ACaptureReplacesARenderedDatasetButNeverItsExports()
        {
            Render();
            var capture = DatasetWriteSession.Begin(_lego, OverwritePolicy.Replace);
            capture.DiscardPartialFiles();

            Export();
            var before = Snapshot();
            var e = Assert.Throws<InvalidParameterException>(() => DatasetWriteSession.Begin(_lego, OverwritePolicy.Replace));
            Assert.That(e.Problems.Single().ToString(), Does.Contain("is an export made with nerf-dataset convert"));
            Assert.That(Snapshot(), Is.EqualTo(before));
        }

        [Test]
        public void ImagesRenderedWhileAPlanWasWritingAreNotReplacedAtItsCommit()
        {
            var plan = DatasetWriteSession.Begin(_lego, OverwritePolicy.Replace, rendersImages: false);
            plan.WriteText(DatasetLayout.ConfigFileName, "{ \"generator\": \"" + PluginInfo.Name + "\", \"imagesRendered\": false }");
            Render();
            var before = Snapshot();
            Assert.Throws<IOException>(() => plan.Commit());
            Assert.That(Snapshot(), Is.EqualTo(before));
            Assert.That(Directory.Exists(plan.WorkingFolder), Is.True, "the new plan is kept to inspect");
        }

        [Test]
        public void AnInterruptedPlanReplaceIsNotFinishedOverImagesRenderedMeanwhile()
        {
            // Stop the replacing plan at each step until it is stopped just before moving the old dataset aside.
            int steps;
            using (var probe = new Scratch())
            {
                var config = probe.WriteText("lego.json", Config);
                Assert.That(ToolRun.Of("plan", "--config", config, "--out", probe.PathOf("lego")).ExitCode, Is.EqualTo(0));
                steps = Interruptions.Steps(out _, "plan", "--config", config, "--out", probe.PathOf("lego"));
            }
            for (var step = 1; step <= steps; step++)
            {
                Interruptions.StopAt(step, "plan", "--config", _config, "--out", _lego);
                var working = Directory.GetDirectories(_scratch.Root, "lego.partial-*~").SingleOrDefault();
                var journal = working == null ? null : OperationJournal.Load(working);
                if (journal?.State == OperationJournal.Committing && Directory.Exists(_lego) && journal.Aside != null && !Directory.Exists(journal.Aside))
                {
                    Render();
                    var before = Snapshot();
                    var clean = ToolRun.Of("clean", _scratch.Root);
                    Assert.That(clean.Out + clean.Err, Does.Contain("could not finish the interrupted write of " + _lego), clean.ToString());
                    Assert.That(Snapshot(), Is.EqualTo(before), "the rendered dataset is untouched\n" + clean);
                    Assert.That(Directory.Exists(working), Is.True, "the complete new plan is kept, not cleaned away\n" + clean);
                    Assert.That(clean.Err, Does.Contain("kept " + working + " (").And.Contain("a complete dataset for " + _lego + " that could not be moved into place"), clean.ToString());
                    Assert.That(clean.ExitCode, Is.EqualTo(1), clean.ToString());
                    return;
                }
                if (working != null) Directory.Delete(working, true);
            }
            Assert.Fail("no step stopped the replace between its journal and moving the old dataset aside");
        }
    }
}
