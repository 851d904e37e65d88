using System;
using System.IO;
using System.Linq;
using System.Runtime.CompilerServices;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Imported nerf_synthetic cameras in a real Unity scene: where the camera goes, and what a capture writes.</summary>
    public class ImportedCamerasTests
    {
        static string LegoTrain([CallerFilePath] string here = "") =>
            Path.Combine(Path.GetDirectoryName(Path.GetDirectoryName(Path.GetDirectoryName(here))), "Core", "Fixtures", "nerf_synthetic_lego", "transforms_train.json");

        [Test]
        public void AUnityCameraAtAnImportedPoseHasTheFilesMatrix()
        {
            // Unity's own Camera.cameraToWorldMatrix (OpenGL camera axes, Unity world) relabelled by the Y/Z swap must
            // give lego's matrices back, up to float32 transforms.
            var imported = TransformsPoseReader.ReadFile(LegoTrain());
            var go = new GameObject("Imported camera test", typeof(Camera));
            try
            {
                var camera = go.GetComponent<Camera>();
                foreach (var c in imported.Cameras.Take(20))
                {
                    c.Pose.ApplyTo(go.transform);
                    var m = camera.cameraToWorldMatrix;
                    for (var col = 0; col < 4; col++)
                    {
                        var unity = new Vector3d(m[0, col], m[1, col], m[2, col]);
                        var output = BlenderConvention.FromUnity(unity);
                        var expected = c.FileCameraToWorld.Column(col);
                        Assert.That(Vector3d.Distance(output, expected), Is.LessThan(1e-5), c.Name + " column " + col);
                    }
                }
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(go);
            }
        }

        [Test, Category("GPU")]
        public void ACaptureOfImportedLegoCamerasWritesLegosMatrices()
        {
            TestScene.RequireRendering();
            var scene = TestScene.Open();
            var project = Path.Combine(Path.GetTempPath(), "nerf-imported-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(project);
            try
            {
                var sphere = TestScene.LitSphere("Imported cameras sphere");
                var lego = JObject.Parse(File.ReadAllText(LegoTrain()));
                var frames = new JArray(((JArray)lego["frames"]).Take(3));
                var subset = Path.Combine(project, "transforms_test.json");
                File.WriteAllText(subset, new JObject { ["camera_angle_x"] = lego["camera_angle_x"], ["frames"] = frames }.ToString());

                var settings = new DatasetSettings { Name = "imported", Width = 16, Height = 16, Normalisation = NormalisationMode.Recentre };
                settings.Train.Count = 2;
                settings.Val.Count = 1;
                settings.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.ImportedPoses, Path = subset, UseFileIntrinsics = true };
                sphere.transform.position = Vector3.zero; // recentring on a target at the origin is the identity
                var prepared = DatasetCapture.Prepare(settings, sphere, project);
                Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
                var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
                Assert.That(result.Succeeded, Is.True, result.Message);

                var written = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, "transforms_test.json")));
                var writtenFrames = (JArray)written["frames"];
                Assert.That(writtenFrames, Has.Count.EqualTo(3));
                for (var i = 0; i < 3; i++)
                    Assert.That(writtenFrames[i]["transform_matrix"].ToObject<double[][]>(), Is.EqualTo(frames[i]["transform_matrix"].ToObject<double[][]>()), "frame " + i);
                Assert.That((double)written["camera_angle_x"], Is.EqualTo((double)lego["camera_angle_x"]).Within(1e-9));
            }
            finally
            {
                TestScene.Close(scene);
                if (Directory.Exists(project)) Directory.Delete(project, true);
            }
        }

        sealed class SilentProgress : ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
