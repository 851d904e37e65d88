using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class NormalisedRunTests
    {
        static readonly PlanTarget Target = new PlanTarget(new Vector3d(1, 2, 3), 0.5);
        TempFolder _temp;
        string _project;

        [SetUp]
        public void CreateProject()
        {
            _temp = new TempFolder();
            _project = _temp.Path;
        }

        [TearDown]
        public void DeleteProject() => _temp.Dispose();

        /// <summary>Distance 8 with the nerf_synthetic preset: s = 4/8 = 0.5.</summary>
        static DatasetSettings HalfScale(int points = 0)
        {
            var settings = new DatasetSettings
            {
                Name = "norm", Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K,
                Distance = 8, Normalisation = NormalisationMode.NerfSyntheticScale, PointCloudPoints = points,
            };
            settings.Train.Count = 1;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            settings.Test.Depth = ExtraOutput.PngAndExr;
            return settings;
        }

        [Test]
        public void DepthFilesHoldOutputUnits()
        {
            var run = DatasetRun.Prepare(HalfScale(), Target, _project);
            Assert.That(run.Problems, Is.Empty);
            var session = run.Begin();
            float[] exr = null;
            var writer = new ViewFileWriter(run.Plan, session, (pixels, w, h, c) =>
            {
                exr = (float[])pixels.Clone();
                return new byte[] { 1 };
            });
            Assert.That(writer.DepthScale, Is.EqualTo(0.5));
            writer.Write(run.Plan.ViewsOf(DatasetSplit.Test).Single(), SyntheticViews.Colour(), SyntheticViews.Data());
            run.Finish(session, new Provenance(new DateTime(2026, 11, 22, 12, 0, 0, DateTimeKind.Utc)));

            // The depth pass holds 2 + 0.1·row Unity units (row 0 at the bottom); output units are half of that.
            var png = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(run.DatasetFolder, "test", "r_0_depth_0000.png")));
            int Thousandths(int x, int y) => png.Pixels[(y * png.Width + x) * 2] << 8 | png.Pixels[(y * png.Width + x) * 2 + 1];
            Assert.That(Thousandths(0, 7), Is.EqualTo(1000), "2 Unity units × 0.5 = 1 output unit");
            Assert.That(Thousandths(0, 0), Is.EqualTo(1350), "2.7 × 0.5");
            Assert.That(Thousandths(7, 0), Is.EqualTo(0), "no surface stays 0");
            // EXR rows go bottom-first (Unity's EncodeArrayToEXR order).
            Assert.That(exr[0], Is.EqualTo(1.0f));
            Assert.That(exr[7 * SyntheticViews.Width], Is.EqualTo((float)(2.7f * 0.5)));
            Assert.That(exr[7], Is.EqualTo(0f));

            var test = JObject.Parse(File.ReadAllText(Path.Combine(run.DatasetFolder, "transforms_test.json")));
            Assert.That((double)test["integer_depth_scale"], Is.EqualTo(0.001), "thousandths of an output unit");
            Assert.That((double)test["scene_normalisation"]["scale"], Is.EqualTo(0.5));
        }

        [Test]
        public void DepthAtScaleOneIsUnchanged()
        {
            // The recentred default: the encoders see the depth pass's floats bit for bit.
            var frame = SyntheticViews.Data();
            var plain = new float[SyntheticViews.Width * SyntheticViews.Height];
            var scaled = new float[plain.Length];
            DepthEncoding.ToMetres(frame, plain, RowDirection.TopRowFirst);
            DepthEncoding.ToMetres(frame, scaled, RowDirection.TopRowFirst, 1);
            Assert.That(scaled, Is.EqualTo(plain));
            Assert.Throws<InvalidParameterException>(() => DepthEncoding.ToMetres(frame, scaled, RowDirection.TopRowFirst, 0));
            Assert.Throws<InvalidParameterException>(() => DepthEncoding.ToMillimetres(frame, new ushort[plain.Length], double.NaN));
        }

        /// <summary>A 2×2 square in Unity's y = 3 plane (facing +y), centred on the target.</summary>
        static SurfaceMesh Square() => new SurfaceMesh(
            new[] { new Vector3d(0, 3, 2), new Vector3d(2, 3, 2), new Vector3d(2, 3, 4), new Vector3d(0, 3, 4) },
            new[] { 0, 2, 1, 0, 3, 2 },
            Enumerable.Repeat(new Vector3d(0, 1, 0), 4).ToList(),
            triangleColors: new[] { new Vector3d(1, 0, 0), new Vector3d(1, 0, 0) });

        [Test]
        public void ThePointCloudLiesOnTheNormalisedSurface()
        {
            var plan = CapturePlan.Build(HalfScale(points: 500), Target);
            var points = TargetPointCloud.Sample(plan, new[] { Square() });
            Assert.That(points, Has.Count.EqualTo(500));
            foreach (var p in points)
            {
                // Unity (x, 3, z), x, z ∈ [0, 2] × [2, 4], minus the centre (1, 2, 3), relabelled (x, z, y), × 0.5.
                Assert.That(p.Position.Z, Is.EqualTo(0.5).Within(1e-12));
                Assert.That(Math.Abs(p.Position.X), Is.LessThanOrEqualTo(0.5 + 1e-12));
                Assert.That(Math.Abs(p.Position.Y), Is.LessThanOrEqualTo(0.5 + 1e-12));
                Assert.That(p.Normal, Is.EqualTo(new Vector3d(0, 0, 1)), "Unity +y is output +z");
                Assert.That(new[] { p.Red, p.Green, p.Blue }, Is.EqualTo(new byte[] { 255, 0, 0 }));
            }
            var again = TargetPointCloud.Sample(plan, new[] { Square() });
            Assert.That(again.Select(p => p.Position), Is.EqualTo(points.Select(p => p.Position)), "seeded");
            var expected = SurfaceSampler.Sample(new[] { Square() }, 500, SeededRandom.Derive(plan.Settings.Seed, "points3d"));
            Assert.That(points[17].Position, Is.EqualTo(expected[17].FromUnityWorld(plan.Normalisation).Position));
        }

        [Test]
        public void ARunWritesPoints3dPlyThatReadsBack()
        {
            var run = DatasetRun.Prepare(HalfScale(points: 64), Target, _project);
            Assert.That(run.WritesPointCloud, Is.True);
            var points = TargetPointCloud.Sample(run.Plan, new[] { Square() });
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
            run.Finish(session, new Provenance(new DateTime(2026, 11, 22, 12, 0, 0, DateTimeKind.Utc)), points);

            var read = PlyReader.Read(Path.Combine(run.DatasetFolder, "points3d.ply"));
            Assert.That(read, Has.Count.EqualTo(64));
            for (var i = 0; i < read.Count; i++)
            {
                Assert.That((read[i].Position - points[i].Position).Length, Is.LessThan(1e-6), "float32 in the file");
                Assert.That(read[i].Normal, Is.EqualTo(points[i].Normal));
                Assert.That(read[i].Red, Is.EqualTo(points[i].Red));
            }
            Assert.That(DatasetValidator.Validate(run.DatasetFolder).Problems, Is.Empty);

            // dataset_config.json records the file with its SHA-256, so convert and validate know it is ours.
            var config = JObject.Parse(File.ReadAllText(Path.Combine(run.DatasetFolder, "dataset_config.json")));
            Assert.That((string)config["pointCloud"]["file"], Is.EqualTo("points3d.ply"));
            Assert.That((int)config["pointCloud"]["points"], Is.EqualTo(64));
            Assert.That((string)config["pointCloud"]["sha256"], Is.EqualTo(PointCloudRecord.HashOf(Path.Combine(run.DatasetFolder, "points3d.ply"))));
            Assert.That(DatasetValidator.Validate(run.DatasetFolder).Warnings.Select(w => w.File), Does.Not.Contain("points3d.ply"));
        }

        [Test]
        public void NoPointsNoFile()
        {
            var run = DatasetRun.Prepare(HalfScale(), Target, _project);
            Assert.That(run.WritesPointCloud, Is.False);
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
            run.Finish(session, new Provenance(DateTime.UtcNow));
            Assert.That(File.Exists(Path.Combine(run.DatasetFolder, "points3d.ply")), Is.False);
        }

        [Test]
        public void OnlyShardZeroWritesTheCloud()
        {
            var settings = HalfScale(points: 10);
            Assert.That(DatasetRun.Prepare(settings, Target, _project, new ShardSpec(0, 2), "s0").WritesPointCloud, Is.True);
            Assert.That(DatasetRun.Prepare(settings, Target, _project, new ShardSpec(1, 2), "s1").WritesPointCloud, Is.False);
        }

        [Test]
        public void APointCloudNeedsASurface()
        {
            var settings = HalfScale(points: 10);
            Assert.That(TargetPointCloud.Check(settings, new List<SurfaceMesh>()).Select(p => p.Field), Is.EqualTo(new[] { "pointCloudPoints" }));
            var flat = new SurfaceMesh(new[] { Vector3d.Zero, Vector3d.UnitX, 2 * Vector3d.UnitX }, new[] { 0, 1, 2 });
            Assert.That(TargetPointCloud.Check(settings, new[] { flat })[0].Reason, Does.Contain("zero area"));
            Assert.That(TargetPointCloud.Check(settings, new[] { Square() }), Is.Empty);
            Assert.That(TargetPointCloud.Check(new DatasetSettings(), new List<SurfaceMesh>()), Is.Empty, "none asked for");
        }
    }
}
