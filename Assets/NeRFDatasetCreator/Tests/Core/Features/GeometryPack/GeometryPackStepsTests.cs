using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>"geometryPack": "everyStep"</c>: a multi-view dynamic capture of the analytic scene, whose opaque sphere moves
    /// 0.4 Unity units along +X over the range, written through the capture's own Core path with one mesh per step.
    /// Each step's mesh lines up with that step's depth maps and not with another's; evaluate picks the step's mesh and
    /// train views, scores the right step well and a wrong one badly, refuses an ambiguous step; merge carries the
    /// per-step files over consistently and refuses a changed one.
    /// </summary>
    public class GeometryPackStepsTests
    {
        const int Steps = 3;

        static AnalyticDataset.Options Options(bool everyStep = true) => new AnalyticDataset.Options
        {
            Width = 160, Height = 120, Supersampling = 1, Train = 4, Val = 1, Test = 2, TimeSteps = Steps, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = everyStep,
        };

        static JObject Config(string folder) => JObject.Parse(File.ReadAllText(Path.Combine(folder, DatasetLayout.ConfigFileName)));

        [Test]
        public void TheSettingReadsWritesAndRefusesClearly()
        {
            var s = DatasetSettingsJson.Read("{\"geometryPack\": \"everyStep\"}").Settings;
            Assert.That(s.GeometryPack && s.GeometryPackEveryStep, Is.True);
            Assert.That(DatasetSettingsJson.Write(s), Does.Contain("\"geometryPack\": \"everyStep\""));
            Assert.That(s.Clone().GeometryPackEveryStep, Is.True);
            var off = DatasetSettingsJson.Read("{\"geometryPack\": false}").Settings;
            Assert.That(off.GeometryPack || off.GeometryPackEveryStep, Is.False);
            Assert.That(DatasetSettingsJson.Read(DatasetSettingsJson.Write(s)).Settings.GeometryPackEveryStep, Is.True, "round trip");
            var error = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"geometryPack\": \"everystep\"}"));
            Assert.That(error.Message, Does.Contain("geometryPack").And.Contain("must be true, false or \"everyStep\"").And.Contain("Did you mean \"everyStep\""));
            Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"geometryPack\": 1}"));
        }

        [Test]
        public void EveryStepsMeshIsWrittenRecordedAndValid()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "steps", Options());
                Assert.That(File.Exists(Path.Combine(folder, TargetMeshPly.RelativePath)), Is.False, "the steps replace the start-only mesh");
                var entries = GeometryPackStepRecord.Entries(Config(folder));
                Assert.That(entries.Select(e => e.Step), Is.EqualTo(new int?[] { 0, 1, 2 }));
                Assert.That(entries.Select(e => e.File), Is.EqualTo(new[] { "geometry/target_mesh_t0000.ply", "geometry/target_mesh_t0001.ply", "geometry/target_mesh_t0002.ply" }));
                Assert.That(entries.Select(e => e.Time), Is.EqualTo(new double?[] { 0, 0.5, 1 }), "the views' time keys of each step");
                Assert.That(entries.Select(e => e.Seconds), Is.EqualTo(new double?[] { 0, 0.5, 1 }));
                var expectedTriangles = AnalyticSceneMeshes.At(0).Sum(m => (long)m.TriangleCount);
                Assert.That(entries.Select(e => e.Triangles), Is.All.EqualTo(expectedTriangles));
                var record = (JObject)Config(folder)["geometry"];
                Assert.That((bool)record["everyStep"], Is.True);
                Assert.That(((JArray)record["steps"])[1]["objects"].Select(o => (string)o["name"]), Is.EqualTo(new[] { "opaque", "glass", "slab" }));
                foreach (var e in entries) Assert.That(PointCloudRecord.HashOf(Path.Combine(folder, e.File)), Is.EqualTo(e.Sha256));

                Assert.That(DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()), Is.Empty);
                Assert.That(DatasetValidator.Validate(folder).Warnings.Select(p => p.ToString()), Has.None.Contains("geometry"));
                Assert.That(OwnDataset.WhyNotOurs(folder), Is.Null, "the numbered files are the product's");

                // A changed step file and an unrecorded one are reported.
                File.AppendAllText(Path.Combine(folder, entries[2].File), " ");
                File.WriteAllText(Path.Combine(folder, "geometry", "target_mesh_t0009.ply"), "ply");
                var report = DatasetValidator.Validate(folder);
                Assert.That(report.Problems.Select(p => p.ToString()), Has.Some.Contains("target_mesh_t0002.ply").And.Some.Contains("SHA-256"));
                Assert.That(report.Warnings.Select(p => p.ToString()), Has.Some.Contains("target_mesh_t0009.ply"));
                Assert.That(OwnDataset.WhyNotOurs(Path.Combine(folder)), Is.Null, "still only names the product writes");
                File.WriteAllText(Path.Combine(folder, "geometry", "notes.txt"), "mine");
                Assert.That(OwnDataset.WhyNotOurs(folder), Is.Not.Null, "a foreign file in geometry/ makes it someone else's");
            }
        }

        [Test]
        public void WithoutEveryStepADynamicCaptureWritesTheStartMeshWithItsTime()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "start", Options(everyStep: false));
                var record = (JObject)Config(folder)["geometry"];
                Assert.That((string)record["file"], Is.EqualTo(TargetMeshPly.RelativePath));
                Assert.That((int)record["step"], Is.EqualTo(0));
                Assert.That((double)record["time"], Is.EqualTo(0));
                Assert.That(Directory.GetFiles(Path.Combine(folder, "geometry")).Select(Path.GetFileName), Is.EqualTo(new[] { TargetMeshPly.FileName }));
            }
        }

        /// <summary>The share of points on step <paramref name="meshStep"/>'s moving sphere that the train views of step <paramref name="viewStep"/> see at their depth.</summary>
        static double SeenShare(string folder, int meshStep, int viewStep)
        {
            var config = Config(folder);
            var entry = GeometryPackStepRecord.Entries(config)[meshStep];
            var mesh = GeometryFile.Read(Path.Combine(folder, entry.File));
            // The PLY's faces are in the record's object order: the opaque (moving) sphere's come first.
            var opaque = (int)config["geometry"]["steps"][meshStep]["objects"][0]["triangles"];
            var sphere = new SurfaceMesh(mesh.Vertices, mesh.Triangles.Take(3 * opaque).ToList(), null);
            var points = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { sphere }, 20000, 5));
            var observed = new bool[points.Length / 3];
            var train = EvaluationDataset.Read(folder, "train");
            foreach (var frame in train.Frames.Where(f => f.TimeStep == viewStep))
            {
                var png = PngReader.Read(frame.DepthPath);
                ObservedPoints.Mark(points, observed, frame.CameraToWorld, EvaluationImages.DepthPng(png, train.DepthScale, frame.DepthPath), png.Width, png.Height,
                    train.Focal(png.Width), png.Width / 2.0, png.Height / 2.0, 0.003, 0.5);
            }
            return observed.Count(o => o) / (double)observed.Length;
        }

        [Test]
        public void EachStepsMeshLinesUpWithThatStepsDepthMaps()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "align", Options());
                var shares = new double[Steps, Steps];
                for (var k = 0; k < Steps; k++)
                    for (var j = 0; j < Steps; j++)
                        shares[k, j] = SeenShare(folder, k, j);
                TestContext.WriteLine("seen shares (mesh step × view step): " + string.Join("; ", Enumerable.Range(0, Steps).Select(k => string.Join(" ", Enumerable.Range(0, Steps).Select(j => shares[k, j].ToString("0.000"))))));
                for (var k = 0; k < Steps; k++)
                {
                    // Four cameras around the scene see over half of the sphere at its own time (the glass sphere and the slab hide some).
                    Assert.That(shares[k, k], Is.GreaterThan(0.4), "step " + k + " against its own views");
                    for (var j = 0; j < Steps; j++)
                        if (j != k) Assert.That(shares[k, j], Is.LessThan(shares[k, k] / 10), "step " + k + "'s sphere against step " + j + "'s views (it moved 0.2 units)");
                }
            }
        }

        [Test]
        public void TheSelfCheckComparesEachStepsMeshWithThatStepsDepthAndCatchesASwap()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "check", Options());
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                var result = report.Results.Single(r => r.Name == GeometryPackDepthCheck.CheckName);
                TestContext.WriteLine(result.Figure);
                Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Passed), result.Figure + " " + result.Reason);
                Assert.That(result.Figure, Does.StartWith("21 views, 3 meshes"), "(4 train + 1 val + 2 test cameras) × 3 steps, each against its own step's mesh");

                // Step 2's file holds step 0's surface: the views at time 1 see the sphere elsewhere.
                // A capture that wrote the wrong mesh records that mesh's SHA-256, so the record agrees with the file and
                // only the comparison with depth can catch it (a file changed after the capture fails on its hash alone).
                File.Copy(Path.Combine(folder, GeometryPackSteps.RelativePath(0)), Path.Combine(folder, GeometryPackSteps.RelativePath(2)), true);
                var configPath = Path.Combine(folder, DatasetLayout.ConfigFileName);
                var config = Config(folder);
                var hash0 = GeometryPackStepRecord.Entries(config).Single(e => e.Step == 0).Sha256;
                foreach (var step in config.SelectTokens("$..steps[?(@.step == 2)]")) step["sha256"] = hash0;
                File.WriteAllText(configPath, config.ToString());
                Assert.That(GeometryPackStepRecord.Entries(Config(folder)).Single(e => e.Step == 2).Sha256, Is.EqualTo(hash0));
                var swapped = DatasetCheck.Run(folder, new DatasetCheckOptions());
                Assert.That(swapped.Results.Single(r => r.Name == GeometryPackDepthCheck.CheckName).Status, Is.EqualTo(DatasetCheckStatus.Failed));
                Assert.That(swapped.Problems.Where(p => p.Check == GeometryPackDepthCheck.CheckName).Select(p => p.Message), Has.All.Contains("time step 2").And.All.Contains("in front of the depth"));
            }
        }

        [Test]
        public void EvaluateScoresTheRightStepWellAndAWrongStepBadly()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "eval", Options());
                var dataset = EvaluationDataset.Read(folder, "test");
                // The "reconstruction" is step 1's ground truth itself, so the right step is perfect up to sampling.
                var recon = Path.Combine(temp.Path, "recon_step1.ply");
                File.Copy(Path.Combine(folder, GeometryPackSteps.RelativePath(1)), recon);
                var right = GeometryEvaluation.Run(dataset, recon, null, 0.02, 40000, null, 1);
                var wrong = GeometryEvaluation.Run(dataset, recon, null, 0.02, 40000, null, 0);
                TestContext.WriteLine("right step: Chamfer " + right.Distances.Chamfer + ", F " + right.Distances.FScore + "; wrong step: Chamfer " + wrong.Distances.Chamfer + ", F " + wrong.Distances.FScore);
                Assert.That(right.Step, Is.EqualTo(1));
                Assert.That(right.TruthPath, Does.EndWith("target_mesh_t0001.ply"));
                Assert.That(right.TrainViewsUsed, Is.EqualTo(4), "the four cameras of step 1, not all twelve train views");
                Assert.That(right.ObservedRule, Does.Contain("time step 1"));
                Assert.That(right.Distances.FScore, Is.GreaterThan(0.98));
                Assert.That(wrong.Distances.FScore, Is.LessThan(0.9));
                // The right step's Chamfer is the sampling's own spacing (40 000 points); the wrong step's sphere is 0.2 × 0.5 units off.
                Assert.That(wrong.Distances.Chamfer, Is.GreaterThan(3 * right.Distances.Chamfer));
            }
        }

        [Test]
        public void AMonocularCapturesStepIsItsOneTrainViewFoundByTime()
        {
            using (var temp = new TempFolder())
            {
                // Monocular frames have no time_step: train view i is step i, at time i/3; test views 1 and 2 lie between steps.
                var options = new AnalyticDataset.Options
                {
                    Width = 160, Height = 120, Supersampling = 1, Train = 4, Val = 1, Test = 3, TimeSteps = 4, Monocular = true, PointCloud = 0,
                    MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
                };
                var folder = AnalyticDataset.Write(temp.Path, "mono", options);
                var entries = GeometryPackStepRecord.Entries(Config(folder));
                Assert.That(entries.Select(e => e.Time.Value), Is.EqualTo(new[] { 0, 1 / 3.0, 2 / 3.0, 1 }).Within(1e-12));
                var train = EvaluationDataset.Read(folder, "train");
                Assert.That(train.Frames.Select(f => f.TimeStep), Is.All.Null, "the transforms writer gives monocular frames no time_step");

                var dataset = EvaluationDataset.Read(folder, "test");
                var recon = Path.Combine(folder, GeometryPackSteps.RelativePath(2));
                var truth = GeometryTruth.Resolve(dataset, recon, null, 2);
                Assert.That(truth.TrainFrames.Select(f => f.Index), Is.EqualTo(new[] { 2 }), "train view 2 is step 2");
                var own = GeometryTruth.Resolve(dataset, recon, recon, 2);
                Assert.That(own.TrainFrames.Select(f => f.Index), Is.EqualTo(new[] { 2 }), "with --gt-mesh the step's time comes from the time record");
                var result = GeometryEvaluation.Run(truth, recon, 0.02, 30000, null);
                Assert.That(result.TrainViewsUsed, Is.EqualTo(1));
                Assert.That(result.Distances.FScore, Is.GreaterThan(0.95));

                var check = DatasetCheck.Run(folder, new DatasetCheckOptions()).Results.Single(r => r.Name == GeometryPackDepthCheck.CheckName);
                Assert.That(check.Status, Is.EqualTo(DatasetCheckStatus.Passed), check.Figure + " " + check.Reason);
                Assert.That(check.Figure, Does.StartWith("6 views, 4 meshes"), "4 train + val 0 + test 0 at step times; test 1 and 2 lie between steps");
            }
        }

        static string Field(Action run) => Assert.Throws<InvalidParameterException>(() => run()).Problems[0].ToString();

        [Test]
        public void AnAmbiguousStepIsRefusedNamingStep()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "ambiguous", Options());
                var dataset = EvaluationDataset.Read(folder, "test");
                var recon = Path.Combine(folder, GeometryPackSteps.RelativePath(0));
                Assert.That(Field(() => GeometryTruth.Resolve(dataset, recon, null, null)), Does.Contain("--step").And.Contain("one mesh per time step").And.Contain("step 0 = time 0 … step 2 = time 1"));
                Assert.That(Field(() => GeometryTruth.Resolve(dataset, recon, null, 7)), Does.Contain("--step").And.Contain("is not a step of the geometry pack"));
                Assert.That(Field(() => GeometryTruth.Resolve(dataset, recon, recon, null)), Does.Contain("--step").And.Contain("--gt-mesh on a dynamic dataset"));
                var withMesh = GeometryTruth.Resolve(dataset, recon, recon, 2);
                Assert.That(withMesh.Source, Does.StartWith("--gt-mesh"));
                Assert.That(withMesh.TrainFrames.Select(f => f.TimeStep), Is.All.EqualTo(2));

                var start = AnalyticDataset.Write(temp.Path, "startonly", Options(everyStep: false));
                var startDataset = EvaluationDataset.Read(start, "test");
                Assert.That(GeometryTruth.Resolve(startDataset, recon, null, null).Step, Is.EqualTo(0), "the start-only pack is step 0");
                Assert.That(Field(() => GeometryTruth.Resolve(startDataset, recon, null, 1)), Does.Contain("start time only").And.Contain("everyStep"));

                var still = new AnalyticDataset.Options { Width = 32, Height = 24, Supersampling = 1, Train = 2, Val = 1, Test = 1, PointCloud = 0, MeshesAt = AnalyticSceneMeshes.At };
                var staticFolder = AnalyticDataset.Write(temp.Path, "still", still);
                Assert.That(Field(() => GeometryTruth.Resolve(EvaluationDataset.Read(staticFolder, "test"), recon, null, 0)), Does.Contain("--step").And.Contain("static capture"));
                Assert.That(GeometryTruth.Resolve(EvaluationDataset.Read(staticFolder, "test"), recon, null, null).Step, Is.Null);
            }
        }

        [Test]
        public void AFolderOfPerStepReconstructionsIsScoredStepByStepThroughTheCommand()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "folder", Options());
                var recons = Directory.CreateDirectory(Path.Combine(temp.Path, "meshes")).FullName;
                // Steps 0 and 2 reconstructed, step 2's file holding step 0's mesh (a model that failed to move).
                File.Copy(Path.Combine(folder, GeometryPackSteps.RelativePath(0)), Path.Combine(recons, "mesh_0000.ply"));
                File.Copy(Path.Combine(folder, GeometryPackSteps.RelativePath(0)), Path.Combine(recons, "mesh_0002.ply"));
                var renders = Directory.CreateDirectory(Path.Combine(temp.Path, "renders")).FullName;
                foreach (var image in Directory.GetFiles(Path.Combine(folder, "test"), "r_*.png").Where(f => !Path.GetFileName(f).Contains("_0000")))
                    File.Copy(image, Path.Combine(renders, Path.GetFileName(image)));
                var options = new EvaluationOptions { DatasetFolder = folder, RendersFolder = renders, GeometryPath = recons, Threshold = 0.02, TruthPoints = 30000, Threads = 1 };
                var stdout = new StringWriter();
                var stderr = new StringWriter();
                Assert.That(EvaluateCommand.Run(options, stdout, stderr), Is.EqualTo(0), stderr.ToString());
                TestContext.WriteLine(stdout);
                Assert.That(stdout.ToString(), Does.Contain("geometry over 2 time steps").And.Contain("no reconstruction for time step 1"));
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", MetricsJson.FileName)));
                var steps = (JArray)metrics["geometry_steps"];
                Assert.That(steps.Select(s => (int)s["step"]), Is.EqualTo(new[] { 0, 2 }));
                Assert.That((double)steps[0]["fscore"], Is.GreaterThan(0.95), "the right mesh, up to the sampling of 30 000 points");
                Assert.That((double)steps[1]["fscore"], Is.LessThan(0.9), "step 2's file is the sphere where it was at step 0");
                Assert.That((double)metrics["geometry_mean_over_steps"]["fscore"], Is.EqualTo(((double)steps[0]["fscore"] + (double)steps[1]["fscore"]) / 2).Within(1e-12));
                Assert.That(File.ReadAllText(Path.Combine(renders, "evaluation-test", ReportHtml.FileName)), Does.Contain("mean over 2 time steps"));

                // Refusals before anything is written: a file without a step number, two files of one step, --step with a folder.
                File.Copy(Path.Combine(recons, "mesh_0000.ply"), Path.Combine(recons, "mesh.ply"));
                Assert.That(Field(() => GeometryStepsEvaluation.Match(EvaluationDataset.Read(folder, "test"), recons)), Does.Contain("mesh.ply").And.Contain("no step number"));
                File.Move(Path.Combine(recons, "mesh.ply"), Path.Combine(recons, "other_2.obj"));
                Assert.That(Field(() => GeometryStepsEvaluation.Match(EvaluationDataset.Read(folder, "test"), recons)), Does.Contain("is step 2, as mesh_0002.ply is"));
                File.Delete(Path.Combine(recons, "other_2.obj"));
                stderr = new StringWriter();
                options.Step = 1;
                options.OutFolder = Path.Combine(temp.Path, "never");
                Assert.That(EvaluateCommand.Run(options, new StringWriter(), stderr), Is.EqualTo(1));
                Assert.That(stderr.ToString(), Does.Contain("error: --step"));
                Assert.That(Directory.Exists(options.OutFolder), Is.False);
            }
        }

        [Test]
        public void MergeCarriesTheStepsOfShardZeroAndRefusesAChangedOne()
        {
            using (var temp = new TempFolder())
            {
                var shards = new List<string>();
                for (var i = 0; i < 2; i++)
                {
                    var o = Options();
                    o.Shard = new ShardSpec(i, 2);
                    o.DatasetFolder = "shard" + i;
                    shards.Add(AnalyticDataset.Write(temp.Path, "steps", o));
                }
                Assert.That(Directory.Exists(Path.Combine(shards[1], "geometry")), Is.False, "only shard 0 writes the pack");
                Assert.That(Config(shards[1])["geometry"], Is.Null);
                var merged = Path.Combine(temp.Path, "merged");
                var result = ShardMerger.Merge(shards, merged);
                Assert.That(result.Problems.Select(p => p.ToString()), Is.Empty);
                Assert.That(result.Warnings, Has.None.Contains("geometry"));
                Assert.That(Config(merged)["geometry"], Is.EqualTo(Config(shards[0])["geometry"]).Using<JToken>((a, b) => JToken.DeepEquals(a, b) ? 0 : 1));
                foreach (var e in GeometryPackStepRecord.Entries(Config(merged)))
                    Assert.That(File.ReadAllBytes(Path.Combine(merged, e.File)), Is.EqualTo(File.ReadAllBytes(Path.Combine(shards[0], e.File))));
                Assert.That(DatasetValidator.Validate(merged).Problems.Select(p => p.ToString()), Is.Empty);
                Assert.That(OwnDataset.WhyNotOurs(merged), Is.Null);

                // A step file changed after the capture: merge refuses rather than carry a mesh that is not the captured one.
                File.AppendAllText(Path.Combine(shards[0], GeometryPackSteps.RelativePath(1)), "x");
                var refused = ShardMerger.Merge(shards, Path.Combine(temp.Path, "merged2"));
                Assert.That(refused.Problems.Select(p => p.ToString()), Has.Some.Contains("target_mesh_t0001.ply").And.Some.Contains("SHA-256"));
                Assert.That(Directory.Exists(Path.Combine(temp.Path, "merged2")), Is.False);
            }
        }
    }
}
