using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// The README's walk-through — the fenced <c>sh</c> block between <c>&lt;!-- walkthrough begin --&gt;</c> and
    /// <c>&lt;!-- walkthrough end --&gt;</c> — run as written: every <c>nerf-dataset</c> line, in order, in an empty
    /// working folder, through the tool's entry point in-process; each exits 0 and leaves the files it promises
    /// (the demo's transforms and check_report.json, each export's main file, the stand-in renders, evaluate's
    /// report.html). Training lines are comments: they need a GPU and a trainer, so they are shown, not run.
    /// </summary>
    [TestFixture]
    public class ReadmeWalkthroughTests
    {
        const string Begin = "<!-- walkthrough begin -->", End = "<!-- walkthrough end -->";

        static string Readme => File.ReadAllText(Path.Combine(InstalledTool.RepositoryRoot, "README.md"));

        /// <summary>The lines inside the block's fence; the fence itself must be the first and last line between the markers.</summary>
        public static List<string> Block(string markdown)
        {
            var lines = markdown.Split('\n').Select(l => l.TrimEnd('\r')).ToList();
            var begin = lines.IndexOf(Begin);
            var end = lines.IndexOf(End);
            Assert.That(begin, Is.GreaterThanOrEqualTo(0), "README.md has the line " + Begin);
            Assert.That(end, Is.GreaterThan(begin), "README.md has the line " + End + " after " + Begin);
            Assert.That(lines.Count(l => l == Begin) + lines.Count(l => l == End), Is.EqualTo(2), "one walk-through");
            var inside = lines.Skip(begin + 1).Take(end - begin - 1).Where(l => l.Trim().Length > 0).ToList();
            Assert.That(inside.First(), Is.EqualTo("```sh"), "the walk-through is one fenced sh block");
            Assert.That(inside.Last(), Is.EqualTo("```"));
            Assert.That(inside.Skip(1).Take(inside.Count - 2), Has.None.StartWith("```"), "one block");
            return inside.Skip(1).Take(inside.Count - 2).ToList();
        }

        static List<string[]> Commands(IEnumerable<string> block) =>
            block.Where(l => !l.TrimStart().StartsWith("#", StringComparison.Ordinal))
                .Select(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries)).ToList();

        [Test]
        public void EveryLineIsAToolCommandOrAComment()
        {
            foreach (var line in Block(Readme).Where(l => !l.TrimStart().StartsWith("#", StringComparison.Ordinal)))
            {
                Assert.That(line, Does.StartWith("nerf-dataset "), "a line the walk-through test runs");
                // Runnable as written: plain words, no shell quoting or placeholders, no trailing comment.
                Assert.That(line, Does.Not.Match(@"[""'<>\[\]|…#]"), line);
            }
        }

        [Test]
        public void ItLeadsFromDemoThroughEveryExportAndTrainingToEvaluate()
        {
            var block = Block(Readme);
            var commands = Commands(block);
            Assert.That(commands.First().Take(2), Is.EqualTo(new[] { "nerf-dataset", "demo" }));
            Assert.That(commands.Select(c => c[1]), Is.SupersetOf(new[] { "demo", "check", "convert", "evaluate" }));
            var targets = commands.Where(c => c[1] == "convert").Select(c => c[Array.IndexOf(c, "--to") + 1]);
            Assert.That(targets, Is.EquivalentTo(ExportTargets.Names), "one convert per export target");
            Assert.That(commands, Has.Some.Contains("--renders-for"), "stand-in renders, so that evaluate runs without training");
            Assert.That(commands.Last()[1], Is.EqualTo("evaluate"));
            var comments = string.Join("\n", block.Where(l => l.TrimStart().StartsWith("#", StringComparison.Ordinal)));
            foreach (var trainer in new[] { "ns-train", "python train.py", "./instant-ngp" })
                Assert.That(comments, Does.Contain(trainer), "the training commands are shown as comments");
        }

        [Test]
        public void EveryCommandRunsAsWrittenAndLeavesWhatItPromises()
        {
            using var scratch = new Scratch();
            var previous = Environment.CurrentDirectory;
            try
            {
                // In-process, so the relative paths of the README resolve against the process's working folder.
                Environment.CurrentDirectory = scratch.Root;
                foreach (var command in Commands(Block(Readme)))
                {
                    var line = string.Join(" ", command);
                    var started = DateTime.UtcNow;
                    var run = ToolRun.Of(command.Skip(1).ToArray());
                    TestContext.Progress.WriteLine("{0}  -> exit {1}, {2:0.0} s", line, run.ExitCode, (DateTime.UtcNow - started).TotalSeconds);
                    Assert.That(run.ExitCode, Is.EqualTo(0), line + "\n" + run);
                    Assert.That(run.Err, Does.Not.Contain("error:"), line);
                    foreach (var promise in Promises(command, run)) Assert.That(promise.Value, Is.True, line + ": " + promise.Key + "\n" + run);
                }
            }
            finally
            {
                Environment.CurrentDirectory = previous;
            }
        }

        /// <summary>What each walk-through command promises, as (what, whether it holds) after it ran.</summary>
        static IEnumerable<KeyValuePair<string, bool>> Promises(string[] command, ToolRun run)
        {
            KeyValuePair<string, bool> Promise(string what, bool holds) => new KeyValuePair<string, bool>(what, holds);
            string Option(string name) => command[Array.IndexOf(command, name) + 1];
            var folder = command[2];
            switch (command[1])
            {
                case "demo" when command.Contains("--renders-for"):
                    yield return Promise("r_0.png", File.Exists(Path.Combine(folder, "r_0.png")));
                    yield return Promise(DemoRenders.NoteFileName, File.Exists(Path.Combine(folder, DemoRenders.NoteFileName)));
                    break;
                case "demo":
                    foreach (var split in DatasetSplits.Names)
                        yield return Promise(DatasetLayout.TransformsFileName(split), File.Exists(Path.Combine(folder, DatasetLayout.TransformsFileName(split))));
                    var report = Path.Combine(folder, DatasetCheck.ReportFileName);
                    yield return Promise(DatasetCheck.ReportFileName + " that passed", File.Exists(report) && !(bool)JObject.Parse(File.ReadAllText(report))["failed"]);
                    if (command.Contains("--preset") && Option("--preset") == "flow")
                        yield return Promise(FlowLayout.RecordFile, File.Exists(Path.Combine(folder, FlowLayout.Folder, "flow.json")));
                    break;
                case "check":
                    // check's last verdict line: "OK (n of m checks ran; …)".
                    yield return Promise("OK", run.Out.Split('\n').Any(line => line == "OK" || line.StartsWith("OK (", StringComparison.Ordinal)));
                    break;
                case "convert":
                    var output = Option("--out");
                    switch (Option("--to"))
                    {
                        case "nerfstudio":
                        case "ngp":
                            yield return Promise(NerfstudioWriter.FileName, File.Exists(Path.Combine(output, NerfstudioWriter.FileName)));
                            break;
                        case "colmap":
                            yield return Promise("sparse/0/cameras.txt", File.Exists(Path.Combine(output, "sparse", "0", "cameras.txt")));
                            break;
                        case "gaussian-grouping":
                            yield return Promise("sparse/0/cameras.txt", File.Exists(Path.Combine(output, "sparse", "0", "cameras.txt")));
                            yield return Promise(GaussianGrouping.ObjectMaskFolder, Directory.Exists(Path.Combine(output, GaussianGrouping.ObjectMaskFolder)));
                            break;
                        case "dynamic3dgs":
                            yield return Promise(Dynamic3DGaussians.TrainMetaFileName, File.Exists(Path.Combine(output, Dynamic3DGaussians.TrainMetaFileName)));
                            break;
                        case "nerfies":
                            yield return Promise(Nerfies.DatasetFileName, File.Exists(Path.Combine(output, Nerfies.DatasetFileName)));
                            yield return Promise("rgb/2x", Directory.Exists(Path.Combine(output, Nerfies.RgbFolder, "2x")));
                            break;
                        case "dycheck":
                            yield return Promise("splits/train.json", File.Exists(Path.Combine(output, DyCheck.SplitsFolder, "train.json")));
                            yield return Promise("depth/1x", Directory.Exists(Path.Combine(output, DyCheck.DepthFolder, "1x")));
                            break;
                        case "llff":
                            yield return Promise(Llff.PosesBoundsFileName, File.Exists(Path.Combine(output, Llff.PosesBoundsFileName)));
                            yield return Promise("images/0000.png", File.Exists(Path.Combine(output, Llff.ImagesFolder, "0000.png")));
                            break;
                        case "neus":
                            yield return Promise(Neus.CamerasFileName, File.Exists(Path.Combine(output, Neus.CamerasFileName)));
                            yield return Promise("mask/000.png", File.Exists(Path.Combine(output, Neus.MaskFolder, "000.png")));
                            break;
                        case "dynerf":
                            yield return Promise(Llff.PosesBoundsFileName, File.Exists(Path.Combine(output, Llff.PosesBoundsFileName)));
                            yield return Promise("cam00/images/0000.png", File.Exists(Path.Combine(output, "cam00", "images", "0000.png")));
                            break;
                        case "replica":
                            yield return Promise(Replica.TrajectoryFileName, File.Exists(Path.Combine(output, Replica.TrajectoryFileName)));
                            yield return Promise("results/" + Replica.ColourName(0), File.Exists(Path.Combine(output, Replica.ResultsFolder, Replica.ColourName(0))));
                            break;
                        case "tum":
                            yield return Promise(TumRgbd.GroundTruth, File.Exists(Path.Combine(output, TumRgbd.GroundTruth)));
                            yield return Promise(TumRgbd.RgbList, File.Exists(Path.Combine(output, TumRgbd.RgbList)));
                            break;
                        case "hdr-nerf":
                            yield return Promise(HdrNerf.ExposureFileName("test"), File.Exists(Path.Combine(output, HdrNerf.ExposureFileName("test"))));
                            yield return Promise("test/r_0_4.png", File.Exists(Path.Combine(output, "test", "r_0_4.png")));
                            break;
                        case "tensoir":
                        case "gs-ir":
                            yield return Promise("test_000/" + TensoIR.Metadata, File.Exists(Path.Combine(output, TensoIR.ViewFolder("test", 0), TensoIR.Metadata)));
                            yield return Promise("transforms_test.json", File.Exists(Path.Combine(output, "transforms_test.json")));
                            break;
                        case "r3dg":
                            yield return Promise("train/r_0_rgb.exr", File.Exists(Path.Combine(output, "train", R3dg.TrainImage("r_0"))));
                            yield return Promise("test/r_0_rgba.png", File.Exists(Path.Combine(output, "test", R3dg.TestImage("r_0"))));
                            break;
                        case "kubric":
                            yield return Promise("scenes/train/" + Kubric.DataRangesFileName, File.Exists(Path.Combine(output, Kubric.ScenesFolder, "train", Kubric.DataRangesFileName)));
                            yield return Promise("scenes/train/forward_flow_00000.png", File.Exists(Path.Combine(output, Kubric.ScenesFolder, "train", Kubric.FrameFile(Kubric.ForwardFlowLayer, 0))));
                            break;
                        case "nsff":
                            yield return Promise("train/flow_i1/00000_fwd.npz", File.Exists(Path.Combine(output, "train", Nsff.FlowFile(0, true))));
                            yield return Promise("train/disp/00000.npy", File.Exists(Path.Combine(output, "train", Nsff.DispFolder, "00000.npy")));
                            break;
                        case "multiscale":
                            yield return Promise("colmap/images_4", Directory.Exists(Path.Combine(output, MultiscaleExport.ColmapFolder, "images_4")));
                            yield return Promise("mipnerf/metadata.json", File.Exists(Path.Combine(output, MipNerfMultiscale.FolderName, MipNerfMultiscale.MetadataFileName)));
                            break;
                        case "shape-of-motion":
                            // Every ordered pair of the demo's 10 track query frames, and their foreground masks.
                            yield return Promise("100 track files", Directory.Exists(Path.Combine(output, "flow3d_preprocessed", "2d_tracks", "1x")) &&
                                Directory.GetFiles(Path.Combine(output, "flow3d_preprocessed", "2d_tracks", "1x"), "*.npy").Length == 100);
                            yield return Promise("track_anything/1x/0_00000.png", File.Exists(Path.Combine(output, "flow3d_preprocessed", "track_anything", "1x", "0_00000.png")));
                            break;
                        default:
                            yield return Promise("a known export target (teach this test what it writes)", false);
                            break;
                    }
                    break;
                case "evaluate":
                    var evaluation = Path.Combine(Option("--renders"), "evaluation-test");
                    yield return Promise(ReportHtml.FileName, File.Exists(Path.Combine(evaluation, ReportHtml.FileName)));
                    yield return Promise(MetricsJson.FileName, File.Exists(Path.Combine(evaluation, MetricsJson.FileName)));
                    break;
                default:
                    yield return Promise("a command this test knows the promises of (teach it)", false);
                    break;
            }
        }
    }
}
