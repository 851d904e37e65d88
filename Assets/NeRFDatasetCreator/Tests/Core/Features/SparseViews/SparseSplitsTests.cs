using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Sparse-view split files: nerf_synthetic's rig (recognised against the lego fixture) gets the lists DietNeRF /
    /// FreeNeRF use, any other rig farthest-point views (hand-derived), and evaluate --split scores only the listed views.
    /// </summary>
    public class SparseSplitsTests
    {
        static List<Vector3d> LegoCentres() =>
            ((JArray)JObject.Parse(File.ReadAllText(Fixtures.LegoTrainPath))["frames"])
            .Select(f => new Vector3d((double)f["transform_matrix"][0][3], (double)f["transform_matrix"][1][3], (double)f["transform_matrix"][2][3])).ToList();

        /// <summary>A transforms file of these centres (identity rotations: only the centres matter here).</summary>
        static void WriteTransforms(string root, string split, IReadOnlyList<Vector3d> centres)
        {
            var frames = new StringBuilder();
            for (var i = 0; i < centres.Count; i++)
            {
                var c = centres[i];
                frames.Append(i == 0 ? "" : ",\n").Append("{\"file_path\": \"./").Append(split).Append("/r_").Append(i).Append("\", \"transform_matrix\": [[1,0,0,")
                    .Append(c.X.ToString("R", CultureInfo.InvariantCulture)).Append("],[0,1,0,").Append(c.Y.ToString("R", CultureInfo.InvariantCulture)).Append("],[0,0,1,")
                    .Append(c.Z.ToString("R", CultureInfo.InvariantCulture)).Append("],[0,0,0,1]]}");
            }
            Directory.CreateDirectory(root);
            File.WriteAllText(Path.Combine(root, "transforms_" + split + ".json"), "{\"camera_angle_x\": 0.69, \"frames\": [\n" + frames + "]}\n");
        }

        static List<Vector3d> Ring(int count, double radius) =>
            Enumerable.Range(0, count).Select(i => new Vector3d(radius * Math.Cos(0.1 + i), radius * Math.Sin(0.1 + i), 0.5 * i)).ToList();

        [Test]
        public void TheEmbeddedRigIsTheLegoFixturesTrainCentres()
        {
            var lego = LegoCentres();
            var table = NerfSyntheticRig.Reference();
            Assert.That(table.Count, Is.EqualTo(100));
            for (var i = 0; i < 100; i++)
                Assert.That(Vector3d.Distance(table[i], lego[i] / lego[i].Length), Is.LessThan(1e-5), "r_" + i);
        }

        [Test]
        public void TheLegoRigIsRecognisedRecentredAndRescaledButNotWithOneCameraMoved()
        {
            var lego = LegoCentres();
            Assert.That(NerfSyntheticRig.Matches(lego, 200), Is.True);
            Assert.That(NerfSyntheticRig.Matches(lego.Select(c => c * 0.25 + new Vector3d(1, 2, 3)).ToList(), 200), Is.True, "the dataset's normalisation moves and scales the rig");
            Assert.That(NerfSyntheticRig.Matches(lego, 199), Is.False, "200 test views");
            var moved = lego.ToList();
            moved[40] = moved[40] + new Vector3d(0, 0, 0.05);
            Assert.That(NerfSyntheticRig.Matches(moved, 200), Is.False, "one camera 5 cm off (1.2 % of the radius)");
            Assert.That(NerfSyntheticRig.Matches(Ring(100, 4), 200), Is.False);
        }

        [Test]
        public void TheCitedListsAreTheOnesInDietNerfAndFreeNerfsCode()
        {
            // DietNeRF run_nerf.py: np.random.seed(0); np.random.choice(i_train, 8, replace=False) — numpy's result, run by hand.
            Assert.That(SparseViewLists.DietNerfTrain8, Is.EqualTo(new[] { 26, 86, 2, 55, 75, 93, 16, 73 }));
            // --testskip 8: frames[::8] of the 200 test frames.
            Assert.That(SparseViewLists.EveryNth(200, SparseViewLists.DietNerfTestSkip), Is.EqualTo(new[] { 0, 8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96, 104, 112, 120, 128, 136, 144, 152, 160, 168, 176, 184, 192 }));
        }

        [Test]
        public void FarthestPointSelectionFollowsTheDocumentedRule()
        {
            // x = 0, 1, 2, 3, 10: mean 3.2, so 10 first; then 0 (10 away from it); then 3 (nearest chosen 3 away; 2 is 2 away, 1 is 1 away).
            var line = new[] { 0.0, 1, 2, 3, 10 }.Select(x => new Vector3d(x, 0, 0)).ToList();
            Assert.That(FarthestViews.Select(line, 3), Is.EqualTo(new[] { 4, 0, 3 }));
            // A tie goes to the lower index: ±1 are equally far from the mean 0.
            Assert.That(FarthestViews.Select(new[] { new Vector3d(-1, 0, 0), new Vector3d(1, 0, 0) }, 1), Is.EqualTo(new[] { 0 }));
        }

        [Test]
        public void ANerfSyntheticRigDatasetGetsThePaperListsAndAnotherRigTheFarthestPointRule()
        {
            using (var temp = new TempFolder())
            {
                var lego = temp.Combine("lego");
                WriteTransforms(lego, "train", LegoCentres());
                WriteTransforms(lego, "test", Ring(200, 4));
                var other = temp.Combine("other");
                var otherTrain = new[] { 0.0, 1, 2, 3, 10 }.Select(x => new Vector3d(x, 0, 1)).ToList();
                WriteTransforms(other, "train", otherTrain);
                WriteTransforms(other, "test", Ring(3, 4));

                var stdout = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "splits", lego }, stdout, new StringWriter()), Is.EqualTo(0));
                Assert.That(ToolCommands.Run(new[] { "splits", other, "--views", "3" }, stdout, new StringWriter()), Is.EqualTo(0));

                var paper = JObject.Parse(File.ReadAllText(Path.Combine(lego, "splits", "sparse_8.json")));
                Assert.That(paper["train"].Select(t => (int)t), Is.EqualTo(new[] { 26, 86, 2, 55, 75, 93, 16, 73 }));
                Assert.That(paper["test"].Select(t => (int)t), Is.EqualTo(Enumerable.Range(0, 25).Select(i => 8 * i)));
                Assert.That(paper["train_files"][0].ToString(), Is.EqualTo("./train/r_26"));
                Assert.That(paper["test_files"][1].ToString(), Is.EqualTo("./test/r_8"));
                Assert.That((string)paper["source"], Does.Contain("ajayjain/DietNeRF").And.Contain("FreeNeRF"));

                var farthest = JObject.Parse(File.ReadAllText(Path.Combine(other, "splits", "sparse_3.json")));
                Assert.That(farthest["train"].Select(t => (int)t), Is.EqualTo(new[] { 4, 0, 3 }));
                Assert.That(farthest["test"].Select(t => (int)t), Is.EqualTo(new[] { 0, 1, 2 }), "every test view");
                Assert.That((string)farthest["rule"], Does.StartWith("farthest-point"));
                Assert.That(farthest["source"], Is.Null);

                // The same lists again: unchanged; other lists where one is: refused, the file untouched.
                var again = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "splits", other, "--views", "3" }, again, new StringWriter()), Is.EqualTo(0));
                Assert.That(again.ToString(), Does.StartWith("unchanged "));
                WriteTransforms(other, "train", otherTrain.Select(c => c + new Vector3d(0, 0, 1)).Reverse().ToList());
                var before = File.ReadAllText(Path.Combine(other, "splits", "sparse_3.json"));
                var stderr = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "splits", other, "--views", "3" }, new StringWriter(), stderr), Is.EqualTo(1));
                Assert.That(stderr.ToString(), Does.Contain("already exists with other lists").And.Contain("nothing was written"));
                Assert.That(File.ReadAllText(Path.Combine(other, "splits", "sparse_3.json")), Is.EqualTo(before));
            }
        }

        [Test]
        public void ViewCountsOutsideTheTrainSplitAreRefused()
        {
            using (var temp = new TempFolder())
            {
                var root = temp.Combine("d");
                WriteTransforms(root, "train", Ring(5, 2));
                var stderr = new StringWriter();
                Assert.That(ToolCommands.Run(new[] { "splits", root, "--views", "5" }, new StringWriter(), stderr), Is.EqualTo(1));
                Assert.That(stderr.ToString(), Does.Contain("--views = 5").And.Contain("fewer than the dataset's 5 train views"));
                Assert.That(Directory.Exists(Path.Combine(root, "splits")), Is.False);
                Assert.That(ToolCommands.Run(new[] { "splits", root, "--views", "0" }, new StringWriter(), stderr = new StringWriter()), Is.EqualTo(2));
                Assert.That(stderr.ToString(), Does.Contain("whole numbers ≥ 1"));
            }
        }
        [Test]
        public void APlanWithSparseViewsWritesItsSplitFilesAndStaysOurs()
        {
            using (var temp = new TempFolder())
            {
                var s = new DatasetSettings { Width = 32, Height = 24, SparseViews = new[] { 3 } };
                s.Train.Count = 10;
                s.Test.Count = 4;
                var text = DatasetSettingsJson.Write(s);
                Assert.That(text, Does.Contain("\"sparseViews\": [\n    3\n  ]").Or.Contain("\"sparseViews\": [3]"));
                Assert.That(DatasetSettingsJson.Read(text).Settings.SparseViews, Is.EqualTo(new[] { 3 }));
                Assert.That(DatasetSettingsJson.Write(new DatasetSettings()), Does.Not.Contain("sparseViews"), "configs without it keep their keys");
                Assert.That(SettingsValidator.Validate(new DatasetSettings { SparseViews = new[] { 100 } }).Select(p => p.ToString()),
                    Has.Some.Contain("sparseViews = 100").And.Some.Contain("fewer than the 100 train views"));

                var folder = temp.Combine("planned");
                TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
                var file = Path.Combine(folder, "splits", "sparse_3.json");
                Assert.That(File.Exists(file), Is.True);
                var views = SparseSplits.ReadViews(folder);
                var expected = FarthestViews.Select(views.Train.Select(v => v.Centre).ToList(), 3);
                var written = JObject.Parse(File.ReadAllText(file));
                Assert.That(written["train"].Select(t => (int)t), Is.EqualTo(expected), "the planned poses are the written ones");
                Assert.That(written["test"].Select(t => (int)t), Is.EqualTo(new[] { 0, 1, 2, 3 }));
                Assert.That(OwnDataset.WhyNotOurs(folder), Is.Null, "splits/ is the plugin's");
                Assert.That(SparseSplits.Find(folder, "sparse_3").Train, Is.EqualTo(expected));

                // One shard of a sharded capture holds a share of the views: it writes none (indices are the whole dataset's).
                var shard = temp.Combine("shard");
                var session = DatasetWriteSession.Begin(shard, OverwritePolicy.Never);
                DatasetMetadataFiles.Write(session, CapturePlan.Build(s, PlanTarget.AtOrigin), new Provenance(new System.DateTime(2026, 1, 2, 3, 4, 5, System.DateTimeKind.Utc)), wholeDataset: false);
                session.Commit();
                Assert.That(File.Exists(Path.Combine(shard, "transforms_train.json")), Is.True);
                Assert.That(Directory.Exists(Path.Combine(shard, "splits")), Is.False);
            }
        }
    }
}
