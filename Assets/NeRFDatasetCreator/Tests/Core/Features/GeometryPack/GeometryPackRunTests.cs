using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>A capture run writes the geometry pack: the target's meshes in the output frame, recorded in dataset_config.json.</summary>
    public class GeometryPackRunTests
    {
        static readonly PlanTarget Target = new PlanTarget(new Vector3d(1, 2, 3), 0.5);

        /// <summary>Distance 8 with the nerf_synthetic preset: s = 4/8 = 0.5, centre the target.</summary>
        static DatasetSettings HalfScale()
        {
            var settings = new DatasetSettings
            {
                Name = "pack", Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K,
                Distance = 8, Normalisation = NormalisationMode.NerfSyntheticScale,
            };
            settings.Train.Count = 1;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            return settings;
        }

        /// <summary>A 2×2 square in Unity's y = 3 plane facing +y (Unity's clockwise front faces seen from +y), centred on the target.</summary>
        static SurfaceMesh Square() => new SurfaceMesh(
            new[] { new Vector3d(0, 3, 2), new Vector3d(2, 3, 2), new Vector3d(2, 3, 4), new Vector3d(0, 3, 4) },
            new[] { 0, 2, 1, 0, 3, 2 },
            Enumerable.Repeat(new Vector3d(0, 1, 0), 4).ToList(), name: "Square");

        [Test]
        public void ARunWritesTheTargetMeshInTheOutputFrame()
        {
            using (var temp = new TempFolder())
            {
                var run = DatasetRun.Prepare(HalfScale(), Target, temp.Path);
                Assert.That(run.WritesGeometryPack, Is.True);
                var session = run.Begin();
                var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
                foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
                run.Finish(session, new Provenance(new DateTime(2026, 11, 27, 12, 0, 0, DateTimeKind.Utc)), null, new[] { Square() });

                var path = Path.Combine(run.DatasetFolder, "geometry", "target_mesh.ply");
                var mesh = GeometryFile.Read(path);
                // Unity (x, 3, z) − centre (1, 2, 3) relabelled (x, z, y), × 0.5: the square lies at output z = 0.5.
                Assert.That(mesh.Vertices.Select(v => v.Z), Is.All.EqualTo(0.5).Within(1e-7));
                Assert.That((mesh.Vertices[2] - new Vector3d(0.5, 0.5, 0.5)).Length, Is.LessThan(1e-7), "Unity (2, 3, 4)");
                Assert.That(mesh.VertexNormals.Select(n => (n - Vector3d.UnitZ).Length), Is.All.LessThan(1e-7), "Unity +y is output +z");
                for (var t = 0; t < mesh.Triangles.Count; t += 3)
                {
                    var a = mesh.Vertices[mesh.Triangles[t]];
                    var n = Vector3d.Cross(mesh.Vertices[mesh.Triangles[t + 1]] - a, mesh.Vertices[mesh.Triangles[t + 2]] - a);
                    Assert.That(n.Z, Is.GreaterThan(0), "counter-clockwise seen from the normal's side");
                }

                var config = JObject.Parse(File.ReadAllText(Path.Combine(run.DatasetFolder, "dataset_config.json")));
                var record = config["geometry"];
                Assert.That((string)record["file"], Is.EqualTo("geometry/target_mesh.ply"));
                Assert.That((string)record["sha256"], Is.EqualTo(PointCloudRecord.HashOf(path)));
                Assert.That((int)record["triangles"], Is.EqualTo(2));
                Assert.That((string)record["objects"][0]["name"], Is.EqualTo("Square"));
                Assert.That(GeometryPackRecord.RecordedFile(config), Is.EqualTo(TargetMeshPly.RelativePath));

                Assert.That(OwnDataset.WhyNotOurs(run.DatasetFolder), Is.Null, "the geometry folder is the plugin's own");
                Assert.That(DatasetValidator.Validate(run.DatasetFolder).Problems, Is.Empty);
            }
        }

        [Test]
        public void ShardsOtherThanZeroAndTargetsWithoutMeshesWriteNoPack()
        {
            using (var temp = new TempFolder())
            {
                // One pack per dataset, as points3d.ply: shard 0 writes it and merge carries it over (GeometryPackStepsTests).
                Assert.That(DatasetRun.Prepare(HalfScale(), Target, temp.Path, new ShardSpec(0, 2), "s0").WritesGeometryPack, Is.True, "shard 0 writes the pack");
                Assert.That(DatasetRun.Prepare(HalfScale(), Target, temp.Path, new ShardSpec(1, 2), "s1").WritesGeometryPack, Is.False, "the other shards do not");
                var run = DatasetRun.Prepare(HalfScale(), Target, temp.Path);
                var session = run.Begin();
                var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
                foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
                run.Finish(session, new Provenance(DateTime.UtcNow), null, new SurfaceMesh[0]);
                Assert.That(Directory.Exists(Path.Combine(run.DatasetFolder, "geometry")), Is.False);
                Assert.That(JObject.Parse(File.ReadAllText(Path.Combine(run.DatasetFolder, "dataset_config.json")))["geometry"], Is.Null);
            }
        }

        [Test]
        public void TurnedOffARunWritesNoPackEvenWithMeshes()
        {
            using (var temp = new TempFolder())
            {
                var settings = HalfScale();
                settings.GeometryPack = false;
                var run = DatasetRun.Prepare(settings, Target, temp.Path);
                Assert.That(run.WritesGeometryPack, Is.False);
                var session = run.Begin();
                var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
                foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
                run.Finish(session, new Provenance(DateTime.UtcNow), null, new[] { Square() });
                Assert.That(Directory.Exists(Path.Combine(run.DatasetFolder, "geometry")), Is.False);
                var config = JObject.Parse(File.ReadAllText(Path.Combine(run.DatasetFolder, "dataset_config.json")));
                Assert.That(config["geometry"], Is.Null);
                Assert.That(GeometryPackRecord.RecordedFile(config), Is.Null);
                Assert.That((bool)config["settings"]["geometryPack"], Is.False, "the config says why there is no pack");
                Assert.That(OwnDataset.WhyNotOurs(run.DatasetFolder), Is.Null);
                Assert.That(DatasetValidator.Validate(run.DatasetFolder).Problems, Is.Empty);
            }
        }

        [Test]
        public void TheSettingIsWrittenOnlyWhenOffAndReadBack()
        {
            var s = new DatasetSettings();
            Assert.That(s.GeometryPack, Is.True, "on by default");
            Assert.That(DatasetSettingsJson.Write(s), Does.Not.Contain("geometryPack"), "existing configs keep their keys");
            s.GeometryPack = false;
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text, Does.Contain("\"geometryPack\": false"));
            Assert.That(DatasetSettingsJson.Read(text).Settings.GeometryPack, Is.False);
            Assert.That(DatasetSettingsJson.Read("{\"geometryPack\": true}").Settings.GeometryPack, Is.True);
            Assert.That(DatasetSettingsJson.Read("{}").Settings.GeometryPack, Is.True);
            Assert.That(s.Clone().GeometryPack, Is.False);
            var error = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"geometryPack\": \"no\"}"));
            Assert.That(error.Message, Does.Contain("geometryPack").And.Contain("must be true, false or \"everyStep\""));
        }
    }
}
