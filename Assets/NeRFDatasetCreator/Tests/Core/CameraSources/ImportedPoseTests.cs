using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ImportedPoseTests
    {
        /// <summary>A plan away from the origin, scaled, with every formation kind: poses no identity can hide.</summary>
        static CapturePlan OffCentrePlan(NormalisationMode mode = NormalisationMode.FitTargetRadius)
        {
            var s = new DatasetSettings { Seed = 7, Normalisation = mode, Distance = 3.5, NormalisedTargetRadius = 0.8, Width = 640, Height = 480 };
            s.Train.Count = 12;
            s.Val.Count = 5;
            s.Val.Formation.Kind = FormationKind.Sphere;
            s.Test.Count = 7;
            return CapturePlan.Build(s, new PlanTarget(new Vector3d(1.25, -2, 3.5), 0.9));
        }

        static void AssertSamePose(UnityPose actual, UnityPose expected, double tolerance, string what)
        {
            Assert.That(Vector3d.Distance(actual.Position, expected.Position), Is.LessThan(tolerance), what + " position");
            Assert.That(Vector3d.Distance(actual.Rotation.Right, expected.Rotation.Right), Is.LessThan(tolerance), what + " right");
            Assert.That(Vector3d.Distance(actual.Rotation.Up, expected.Rotation.Up), Is.LessThan(tolerance), what + " up");
            Assert.That(Vector3d.Distance(actual.Rotation.Forward, expected.Rotation.Forward), Is.LessThan(tolerance), what + " forward");
        }

        [Test]
        public void OwnTransformsFilesImportToTheSameUnityPoses()
        {
            var plan = OffCentrePlan();
            foreach (var split in DatasetSplits.All)
            {
                var name = DatasetLayout.TransformsFileName(split);
                var imported = TransformsPoseReader.Read(BlenderTransformsWriter.Write(plan, split), name);
                var views = plan.ViewsOf(split).ToList();
                Assert.That(imported.Cameras, Has.Count.EqualTo(views.Count));
                Assert.That(imported.Normalisation.Scale, Is.EqualTo(plan.Normalisation.Scale), "the file's scene_normalisation record is undone");
                for (var i = 0; i < views.Count; i++)
                {
                    var camera = imported.Cameras[i];
                    AssertSamePose(camera.Pose, views[i].Pose, 1e-9, name + "[" + i + "]");
                    Assert.That(camera.Split, Is.EqualTo(DatasetSplits.Name(split)));
                    Assert.That(camera.Name, Is.EqualTo(views[i].FramePath));
                    Assert.That(camera.Intrinsics.Width, Is.EqualTo(640));
                    Assert.That(camera.Intrinsics.VerticalFovDegrees(0, 0), Is.EqualTo(plan.Settings.Camera.VerticalFovDegrees).Within(1e-9));
                    Assert.That(PosePlacement.ToOutput(camera.FileCameraToWorld, imported.Normalisation, plan.Normalisation), Is.EqualTo(views[i].TransformMatrix),
                        "re-exported under the same normalisation: the written matrix, bit for bit");
                }
            }
        }

        [Test]
        public void HandDerivedMatrixPlacesTheUnityCamera()
        {
            // c2w = identity moved to (1, 2, 3): the OpenGL camera looks along −Z_out = −Y_Unity (down), its up is
            // +Y_out = +Z_Unity, and the Blender point (1, 2, 3) is the Unity point (1, 3, 2).
            var text = "{\"camera_angle_x\": 0.5, \"frames\": [{\"file_path\": \"a\", \"transform_matrix\": [[1,0,0,1],[0,1,0,2],[0,0,1,3],[0,0,0,1]]}]}";
            var camera = TransformsPoseReader.Read(text, "x.json").Cameras.Single();
            AssertSamePose(camera.Pose, new UnityPose(new Vector3d(1, 3, 2), Quaterniond.FromBasis(new Vector3d(1, 0, 0), new Vector3d(0, 0, 1), new Vector3d(0, -1, 0))), 1e-15, "camera");
            Assert.That(camera.Split, Is.Null, "x.json names no split");
            Assert.That(camera.Intrinsics.HasSize, Is.False);
            Assert.That(camera.Intrinsics.VerticalFovDegrees(200, 100), Is.EqualTo(2 * Math.Atan(Math.Tan(0.25) / 2) * 180 / Math.PI).Within(1e-12));
        }

        [Test]
        public void RecordedNormalisationIsUndone()
        {
            // x_out = 2·(x_blender − (1, 0, 0)): the file's centre (0, 0, 4) is the Blender point (1, 0, 2), the Unity point (1, 2, 0).
            var text = "{\"camera_angle_x\": 0.5, \"scene_normalisation\": {\"scale\": 2, \"centre\": [1, 0, 0]}, " +
                       "\"frames\": [{\"file_path\": \"a\", \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]}";
            var imported = TransformsPoseReader.Read(text, "x.json");
            Assert.That(imported.Cameras[0].Pose.Position, Is.EqualTo(new Vector3d(1, 2, 0)));
            // Re-exported without normalisation: the raw Blender centre (1, 0, 2), same rotation.
            var raw = PosePlacement.ToOutput(imported.Cameras[0].FileCameraToWorld, imported.Normalisation, SceneNormalisation.Identity);
            Assert.That(raw.Translation, Is.EqualTo(new Vector3d(1, 0, 2)));
            Assert.That(raw.Column(2), Is.EqualTo(Vector3d.UnitZ));
            // A placement given by the caller is used for files that record none.
            var placed = TransformsPoseReader.Read(text.Replace("\"scene_normalisation\": {\"scale\": 2, \"centre\": [1, 0, 0]}, ", ""), "x.json", new SceneNormalisation(new Vector3d(1, 0, 0), 2));
            Assert.That(placed.Cameras[0].Pose.Position, Is.EqualTo(new Vector3d(1, 2, 0)));
        }

        [Test]
        public void NerfSyntheticLegoReexportsItsExactMatrices()
        {
            var imported = TransformsPoseReader.ReadFile(Fixtures.LegoTrainPath);
            var source = (JArray)JObject.Parse(Fixtures.Text("nerf_synthetic_lego", "transforms_train.json"))["frames"];
            Assert.That(imported.Cameras, Has.Count.EqualTo(100));
            Assert.That(imported.Normalisation, Is.Null, "nerf_synthetic records no normalisation: its world is the output world");
            double worst = 0;
            for (var i = 0; i < source.Count; i++)
            {
                var expected = Matrix4x4d.FromRows(source[i]["transform_matrix"].ToObject<double[][]>());
                var camera = imported.Cameras[i];
                Assert.That(camera.Split, Is.EqualTo("train"));
                // Capturing at the origin (recentre on a target at the Unity origin is the identity) writes the file's matrices.
                var recentre = SceneNormalisation.ForTarget(NormalisationMode.Recentre, Vector3d.Zero, 1, 4);
                Assert.That(PosePlacement.ToOutput(camera.FileCameraToWorld, imported.Normalisation, recentre), Is.EqualTo(expected));
                // The Unity camera placed there renders that view up to float32 rounding of the file.
                var rendered = BlenderConvention.CameraToWorld(camera.Pose);
                for (var r = 0; r < 3; r++)
                    for (var c = 0; c < 4; c++)
                        worst = Math.Max(worst, Math.Abs(rendered[r, c] - expected[r, c]));
            }
            Assert.That(worst, Is.LessThan(5e-6), "float32 entries of size 4 are spaced 4.8e-7 apart, and lego's rotations are orthonormal to ~1e-6");
            TestContext.WriteLine("largest difference between the placed Unity camera and lego's float32 matrices: " + worst.ToString("R", System.Globalization.CultureInfo.InvariantCulture));
        }

        [Test]
        public void NerfstudioFileGivesSplitsAndPerFrameIntrinsics()
        {
            var plan = OffCentrePlan(NormalisationMode.Recentre);
            var frames = plan.Views.Select(v => new ExportFrame(DatasetSplits.Name(v.Split), v.FramePath + ".png", v.TransformMatrix)).ToList();
            var scene = new ExportScene("/data", plan.Intrinsics, frames, null, plan.Normalisation);
            var json = NerfstudioWriter.Build(scene, "/data");
            ((JArray)json["frames"])[3]["fl_x"] = 100.0; // nerfstudio lets a frame override the shared camera
            var imported = TransformsPoseReader.Read(ExportJson.Serialise(json), "transforms.json");
            Assert.That(imported.Format, Is.EqualTo("nerfstudio"));
            Assert.That(imported.OfSplit("val").Select(c => c.Name), Is.EqualTo(plan.ViewsOf(DatasetSplit.Val).Select(v => v.FramePath.Substring(2) + ".png")));
            Assert.That(imported.OfSplit("test"), Has.Count.EqualTo(7));
            for (var i = 0; i < plan.Views.Count; i++)
                AssertSamePose(imported.Cameras[i].Pose, plan.Views[i].Pose, 1e-9, "frame " + i);
            Assert.That(imported.Cameras[3].Intrinsics.FlX, Is.EqualTo(100.0));
            Assert.That(imported.Cameras[4].Intrinsics.FlX, Is.EqualTo(plan.Intrinsics.FlX));
            Assert.That(ImportedPoses.SharedIntrinsics(imported.Cameras), Is.Null, "one frame differs");
            Assert.That(ImportedPoses.SharedIntrinsics(imported.OfSplit("test")).Cx, Is.EqualTo(320.0));
        }

        [Test]
        public void ColmapModelRoundTripsToTheSameMatrices()
        {
            var plan = OffCentrePlan();
            var frames = plan.Views.Select(v => new ExportFrame(DatasetSplits.Name(v.Split), v.FramePath.Substring(2) + ".png", v.TransformMatrix)).ToList();
            var names = ColmapTextWriter.ImageNames(frames);
            var imported = ColmapModelReader.Read(ColmapTextWriter.CamerasText(plan.Intrinsics), ColmapTextWriter.ImagesText(frames, names), "sparse/0", plan.Normalisation);
            Assert.That(imported.Cameras, Has.Count.EqualTo(frames.Count));
            for (var i = 0; i < frames.Count; i++)
            {
                var camera = imported.Cameras[i];
                Assert.That(camera.Split, Is.EqualTo(frames[i].Split), "train_r_0.png is a train image");
                for (var r = 0; r < 4; r++)
                    for (var c = 0; c < 4; c++)
                        Assert.That(camera.FileCameraToWorld[r, c], Is.EqualTo(frames[i].CameraToWorld[r, c]).Within(1e-9), "frame " + i + " [" + r + "," + c + "]");
                AssertSamePose(camera.Pose, plan.Views[i].Pose, 1e-9, "frame " + i);
                Assert.That(camera.Intrinsics.FlX, Is.EqualTo(plan.Intrinsics.FlX));
                Assert.That(camera.Intrinsics.Height, Is.EqualTo(480));
            }
        }

        [Test]
        public void ColmapIdentityExtrinsicsAreAnOpenCvCameraAtTheOrigin()
        {
            // R = I, t = (0, 0, −2): the camera centre is −Rᵀt = (0, 0, 2), looking along +z (OpenCV) = −z of OpenGL's
            // third column negated, so the OpenGL c2w is diag(1, −1, −1) with that centre.
            var imported = ColmapModelReader.Read("1 SIMPLE_PINHOLE 100 80 90 50 40\n", "# header\n7 1 0 0 0 0 0 -2 1 a.png\n\n", "m");
            var m = imported.Cameras.Single().FileCameraToWorld;
            Assert.That(m, Is.EqualTo(Matrix4x4d.FromColumns(new Vector3d(1, 0, 0), new Vector3d(0, -1, 0), new Vector3d(0, 0, -1), new Vector3d(0, 0, 2))));
            var k = imported.Cameras[0].Intrinsics;
            Assert.That(new[] { k.FlX, k.FlY, k.Cx, k.Cy }, Is.EqualTo(new[] { 90.0, 90, 50, 40 }));
        }

        [Test]
        public void ColmapPointsLineIsSkippedEvenWhenItLooksLikeAnImage()
        {
            // read_write_model.py reads the line after an image line as its 2D points, whatever it holds.
            var images = "1 1 0 0 0 0 0 0 1 a.png\n2 1 0 0 0 0 0 0 1 b.png\n3 1 0 0 0 1 0 0 1 c.png\n\n";
            var imported = ColmapModelReader.Read("1 PINHOLE 10 10 5 5 5 5", images, "m");
            Assert.That(imported.Cameras.Select(c => c.Name), Is.EqualTo(new[] { "a.png", "c.png" }));
        }

        [Test]
        public void UnsupportedInputsAreRefusedOrReported()
        {
            var fisheye = Assert.Throws<InvalidParameterException>(() => ColmapModelReader.Read("1 OPENCV_FISHEYE 10 10 5 5 5 5 0 0 0 0", "1 1 0 0 0 0 0 0 1 a.png\n\n", "m"));
            Assert.That(fisheye.Message, Does.Contain("OPENCV_FISHEYE").And.Contain("image_undistorter"));
            var radial = ColmapModelReader.Read("1 SIMPLE_RADIAL 10 10 5 5 5 0.1", "1 1 0 0 0 0 0 0 1 a.png\n\n", "m");
            Assert.That(radial.Warnings.Single().Reason, Does.Contain("distortion"));
            var mitsuba = Assert.Throws<InvalidParameterException>(() => TransformsPoseReader.Read("{\"from_mitsuba\": true, \"frames\": []}", "t.json"));
            Assert.That(mitsuba.Message, Does.Contain("Mitsuba"));
            var mirrored = Assert.Throws<InvalidParameterException>(() => TransformsPoseReader.Read(
                "{\"camera_angle_x\": 0.5, \"frames\": [{\"file_path\": \"a\", \"transform_matrix\": [[1,0,0,0],[0,0,1,0],[0,1,0,0],[0,0,0,1]]}]}", "t.json"));
            Assert.That(mirrored.Message, Does.Contain("frames[0].transform_matrix").And.Contain("mirrored"));
            var distorted = TransformsPoseReader.Read("{\"fl_x\": 50, \"w\": 100, \"h\": 100, \"k1\": 0.2, \"frames\": [{\"file_path\": \"a\", \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]}", "t.json");
            Assert.That(distorted.Warnings.Single().Value, Is.EqualTo("k1"));
            Assert.That(distorted.Cameras[0].Intrinsics.FlY, Is.EqualTo(50.0), "fl_y defaults to fl_x");
        }
    }
}
