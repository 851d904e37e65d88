using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 22: clean removed user folders whose names only looked like leftovers. It may remove only a folder with the
    /// exact name the tool writes and, inside, the tool's journal naming that output (or, for a dataset moved aside by a
    /// replace, the plugin's own dataset); everything else is listed as "not ours, left alone".
    /// </summary>
    [TestFixture]
    public class CleanProvesOwnershipTests
    {
        Scratch _scratch;

        [SetUp]
        public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        string UserFolder(params string[] parts)
        {
            var folder = _scratch.PathOf(parts);
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "mine.txt"), "123456789"); // 9 B, as in the issue
            return folder;
        }

        [Test]
        public void FoldersThatOnlyLookLikeLeftoversAreLeftAlone()
        {
            var dataset = RenderedDataset.PlanOnly(_scratch, "lego");
            var photos = UserFolder("photos.partial-2024~");
            var holiday = UserFolder("holiday.replaced-old~");
            Directory.CreateDirectory(_scratch.PathOf("holiday"));
            var notes = UserFolder("lego", ".convert.partial-notes~");
            var merging = UserFolder(".lego.merging-notes");

            foreach (var dryRun in new[] { true, false })
            {
                var run = dryRun ? ToolRun.Of("clean", _scratch.Root, "--dry-run") : ToolRun.Of("clean", _scratch.Root);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
                foreach (var folder in new[] { photos, holiday, notes, merging })
                {
                    Assert.That(File.ReadAllText(Path.Combine(folder, "mine.txt")), Is.EqualTo("123456789"), folder + "\n" + run);
                    Assert.That(run.Out, Does.Contain("not ours, left alone: " + folder + " (1 file, 9 B): its name only resembles the tool's working folders"), run.ToString());
                }
                Assert.That(run.Out, Does.Not.Contain("removed"), run.ToString());
            }
            Assert.That(OwnDataset.WhyNotOurs(dataset), Is.Not.Null.And.Contains(".convert.partial-notes~"), "the user's folder inside also keeps a replace away");
        }

        [Test]
        public void AnExactlyNamedFolderWithoutTheToolsJournalIsLeftAlone()
        {
            RenderedDataset.PlanOnly(_scratch, "lego");
            Directory.CreateDirectory(_scratch.PathOf("other"));
            var noJournal = UserFolder("lego.partial-20240101-120000-0123abcd~");
            var convertNoJournal = UserFolder("lego", ".convert.partial-20240101-120000-0123abcd~");
            // A journal naming another output proves nothing about this one.
            var elsewhere = UserFolder("lego.partial-20240101-120000-89abcdef~");
            new OperationJournal { Operation = "write", Output = _scratch.PathOf("other") }.Save(elsewhere);
            // A folder named as a replaced dataset, but holding no dataset the plugin wrote.
            var replaced = UserFolder("lego.replaced-0123abcd~");
            // A merge's name with a convert's journal: recovery would roll the "convert" back by deleting the folder.
            var mismatched = UserFolder(".lego.merging-0123abcd");
            new OperationJournal { Operation = "convert", Output = _scratch.PathOf("lego") }.Save(mismatched);

            var run = ToolRun.Of("clean", _scratch.Root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            foreach (var folder in new[] { noJournal, convertNoJournal, elsewhere, replaced, mismatched })
                Assert.That(File.Exists(Path.Combine(folder, "mine.txt")), Is.True, folder + "\n" + run);
            Assert.That(run.Out, Does.Contain("not ours, left alone: " + noJournal + " (1 file, 9 B): it holds no journal (.nerf-operation.json) the tool wrote."));
            Assert.That(run.Out, Does.Contain("not ours, left alone: " + convertNoJournal + " (1 file, 9 B): it holds no journal"));
            Assert.That(run.Out, Does.Contain("not ours, left alone: " + elsewhere + " (2 files, ").And.Contain("is not a write into " + _scratch.PathOf("lego")));
            Assert.That(run.Out, Does.Contain("not ours, left alone: " + replaced + " (1 file, 9 B): it has no dataset_config.json"));
            Assert.That(run.Out, Does.Contain("not ours, left alone: " + mismatched + " (2 files, ").And.Contain("is not a merge into " + _scratch.PathOf("lego")));
        }

        [Test]
        public void TheToolsOwnLeftoversAreStillRemoved()
        {
            var config = _scratch.WriteText("c.json", "{ \"splits\": { \"train\": { \"count\": 2 } } }");
            Interruptions.StopAt(8, "plan", "--config", config, "--out", _scratch.PathOf("lego"));
            var partial = Directory.GetDirectories(_scratch.Root, "lego.partial-*~").Single();
            var photos = UserFolder("photos.partial-2024~");
            var run = ToolRun.Of("clean", _scratch.Root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Out, Does.Contain("removed " + partial + " (").And.Contain("not ours, left alone: " + photos));
            Assert.That(Directory.Exists(partial), Is.False);
            Assert.That(Directory.Exists(photos), Is.True);
        }
    }
}
