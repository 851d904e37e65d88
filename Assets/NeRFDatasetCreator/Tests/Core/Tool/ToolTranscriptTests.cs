using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Unity's Dataset Tools run the tool's own command lines in-process (<see cref="ToolTranscript"/>), built by
    /// each command's <c>Arguments</c> (<see cref="ConvertCommand.Arguments"/> …): the same parsing, commands, files and lines as <c>nerf-dataset</c>.
    /// </summary>
    [TestFixture]
    public class ToolTranscriptTests
    {
        static DatasetSettings Small()
        {
            var s = new DatasetSettings { Width = 16, Height = 12 };
            s.Train.Count = 4;
            s.Val.Count = 2;
            s.Test.Count = 2;
            return s;
        }

        [Test]
        public void ValidateRunsTheToolsCommandAndKeepsItsLines()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("lego");
                TestDatasets.FromPlan(folder, CapturePlan.Build(Small(), new PlanTarget(Vector3d.Zero, 0.5)));
                var run = ToolTranscript.Run(ValidateCommand.Arguments(folder));
                var stdout = new StringWriter { NewLine = "\n" };
                var code = ToolCommands.Run(new[] { "validate", folder }, stdout, new StringWriter());
                Assert.That(run.ExitCode, Is.EqualTo(code));
                Assert.That(run.Succeeded, Is.True, run.Output + run.Errors);
                Assert.That(run.Output, Is.EqualTo(stdout.ToString()), "the lines a Unity user reads are the tool's");
                Assert.That(run.Lines.Last(), Is.EqualTo("OK"));
                Assert.That(run.CommandLine, Is.EqualTo("nerf-dataset validate " + folder));
            }
        }

        [Test]
        public void ConvertWritesTheExportAndKeepsWarningsInTheirPlace()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("lego");
                TestDatasets.FromPlan(folder, CapturePlan.Build(Small(), new PlanTarget(Vector3d.Zero, 0.5)));
                var args = ConvertCommand.Arguments(folder, ExportTarget.Colmap);
                Assert.That(args, Is.EqualTo(new[] { "convert", folder, "--to", "colmap" }));
                var run = ToolTranscript.Run(args);
                Assert.That(run.ExitCode, Is.EqualTo(ToolExitCodes.Success), string.Join("\n", run.Lines));
                Assert.That(File.Exists(Path.Combine(folder, "colmap", "sparse", "0", "images.txt")), Is.True);
                // The command prints its warnings (stderr) before "converted …" (stdout); the combined lines keep that order.
                var lines = run.Lines;
                var firstWarning = lines.ToList().FindIndex(l => l.StartsWith("warning: "));
                var converted = lines.ToList().FindIndex(l => l.StartsWith("converted "));
                Assert.That(firstWarning, Is.GreaterThanOrEqualTo(0), "COLMAP lists every split: a warning");
                Assert.That(firstWarning, Is.LessThan(converted));

                var again = ToolTranscript.Run(args);
                Assert.That(again.ExitCode, Is.EqualTo(ToolExitCodes.Failure));
                Assert.That(again.Errors, Does.Contain("already exists"));
            }
        }

        [Test]
        public void ButtonsBuildTheCommandLinesAUserWouldType()
        {
            Assert.That(CheckCommand.Arguments("d"), Is.EqualTo(new[] { "check", "d" }));
            Assert.That(EvaluateCommand.Arguments("d", "r"), Is.EqualTo(new[] { "evaluate", "d", "--renders", "r" }));
            Assert.That(ConvertCommand.Arguments("d", ExportTarget.Colmap, null, depths: true), Is.EqualTo(new[] { "convert", "d", "--to", "colmap", "--depths" }));
            Assert.That(ConvertCommand.Arguments("d", ExportTarget.Ngp, "out"), Is.EqualTo(new[] { "convert", "d", "--to", "ngp", "--out", "out" }));
            Assert.That(ConvertCommand.Arguments("d", ExportTarget.Dynamic3dgs), Is.EqualTo(new[] { "convert", "d", "--to", "dynamic3dgs" }));
            Assert.That(ConvertCommand.Arguments("d", ExportTarget.GaussianGrouping), Is.EqualTo(new[] { "convert", "d", "--to", "gaussian-grouping" }));
            Assert.That(ConvertCommand.Arguments("d", ExportTarget.Nerfstudio, objectName: " Street/Car 3 "), Is.EqualTo(new[] { "convert", "d", "--to", "nerfstudio", "--object", "Street/Car 3" }));
            Assert.That(MergeCommand.Arguments("m", new[] { "s0", "s1" }, moveFiles: true), Is.EqualTo(new[] { "merge", "--out", "m", "--files", "move", "s0", "s1" }));
            Assert.That(CleanCommand.Arguments("NeRFDatasets", dryRun: true), Is.EqualTo(new[] { "clean", "NeRFDatasets", "--dry-run" }));
            // Every one parses without a usage error.
            foreach (var args in new[]
                     {
                         ValidateCommand.Arguments("d"), ConvertCommand.Arguments("d", ExportTarget.Colmap, "o", true),
                         ConvertCommand.Arguments("d", ExportTarget.Nerfstudio, objectName: "Car"),
                         MergeCommand.Arguments("m", new[] { "s0" }, true), CleanCommand.Arguments("c", true),
                     })
                Assert.That(ToolCommandLine.Parse(args).Errors, Is.Empty, string.Join(" ", args));
        }

        [Test]
        public void TheTerminalLineQuotesPathsWithSpaces()
        {
            Assert.That(ToolTranscript.DescribeCommandLine(new[] { "convert", "/data/My Captures/lego", "--to", "ngp" }),
                Is.EqualTo("nerf-dataset convert \"/data/My Captures/lego\" --to ngp"));
            Assert.That(ToolTranscript.DescribeCommandLine(new[] { "validate", "a\"b" }), Is.EqualTo("nerf-dataset validate \"a\\\"b\""));
        }

        [Test]
        public void ShardFoldersAreThoseWithAShardManifestInNameOrder()
        {
            using (var temp = new TempFolder())
            {
                foreach (var name in new[] { "shard-1", "shard-0", "notes" }) Directory.CreateDirectory(temp.Combine(name));
                File.WriteAllText(temp.Combine("shard-1", ShardManifest.FileName), "{}");
                File.WriteAllText(temp.Combine("shard-0", ShardManifest.FileName), "{}");
                Assert.That(MergeCommand.ShardFoldersIn(temp.Path), Is.EqualTo(new[] { temp.Combine("shard-0"), temp.Combine("shard-1") }));
                Assert.That(MergeCommand.ShardFoldersIn(temp.Combine("missing")), Is.Empty);
            }
        }
    }
}
