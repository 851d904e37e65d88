using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// convert stopped (as by kill -9) at every file operation: the next convert into the same output finishes or
    /// rolls back the interrupted one, the export is complete and identical to an uninterrupted one, and the dataset's
    /// own files are untouched.
    /// </summary>
    [TestFixture]
    public class InterruptedConvertTests
    {
        /// <summary>A rendered dataset with a three-point points3d.ply, so that colmap copies it instead of generating 100 000 random points per run.</summary>
        static string Dataset(Scratch scratch)
        {
            var dataset = RenderedDataset.Create(scratch, "ds");
            PlyWriter.Write(Path.Combine(dataset, BlenderDatasetLoader.PointCloudFileName), new[]
            {
                new CloudPoint(new Vector3d(0, 0, 0), new Vector3d(0, 0, 1), 255, 0, 0),
                new CloudPoint(new Vector3d(0.1, 0, 0), new Vector3d(0, 0, 1), 0, 255, 0),
                new CloudPoint(new Vector3d(0, 0.1, 0), new Vector3d(0, 0, 1), 0, 0, 255),
            });
            return dataset;
        }

        [TestCase("colmap", "colmap")]
        [TestCase("nerfstudio", "")]
        public void AConvertKilledAtAnyStepIsFinishedOrRolledBackByTheNextOne(string target, string outputName)
        {
            int steps;
            string expected;
            using (var template = new Scratch())
            using (var probe = new Scratch())
            {
                var original = Dataset(template);
                var dataset = CopyOf(original, probe);
                var before = ShardFolders.Snapshot(dataset);
                steps = Interruptions.Steps(out var run, "convert", dataset, "--to", target);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                expected = Added(before, ShardFolders.Snapshot(dataset));
                Assert.That(expected, Is.Not.Empty);
                for (var step = 1; step <= steps; step++)
                    Interrupt(original, target, outputName, step, steps, expected);
            }
        }

        static void Interrupt(string original, string target, string outputName, int step, int steps, string expected)
        {
                using (var scratch = new Scratch())
                {
                    var dataset = CopyOf(original, scratch);
                    var before = ShardFolders.Snapshot(dataset);
                    Interruptions.StopAt(step, "convert", dataset, "--to", target);
                    var again = ToolRun.Of("convert", dataset, "--to", target);
                    var where = "killed before step " + step + " of " + steps + "\n" + again;
                    Assert.That(again.ExitCode, Is.EqualTo(0), where);
                    var after = ShardFolders.Snapshot(dataset);
                    Assert.That(Added(before, after), Is.EqualTo(expected), where + "\nthe export is complete and the same");
                    Assert.That(before.Split('\n').All(line => after.Split('\n').Contains(line)), Is.True, where + "\nthe dataset's files are untouched");
                    var output = Path.Combine(dataset, outputName);
                    Assert.That(Directory.GetDirectories(output, ".convert.partial-*"), Is.Empty, where + "\nno working folder is left");
                }
        }

        static string CopyOf(string dataset, Scratch scratch)
        {
            var copy = scratch.PathOf("ds");
            foreach (var dir in Directory.GetDirectories(dataset, "*", SearchOption.AllDirectories))
                Directory.CreateDirectory(copy + dir.Substring(dataset.Length));
            Directory.CreateDirectory(copy);
            foreach (var file in Directory.GetFiles(dataset, "*", SearchOption.AllDirectories))
                File.Copy(file, copy + file.Substring(dataset.Length));
            return copy;
        }

        /// <summary>The snapshot lines of <paramref name="after"/> that <paramref name="before"/> lacks.</summary>
        static string Added(string before, string after)
        {
            var old = before.Split('\n').ToHashSet();
            return string.Join("\n", after.Split('\n').Where(l => !old.Contains(l)));
        }
    }
}
