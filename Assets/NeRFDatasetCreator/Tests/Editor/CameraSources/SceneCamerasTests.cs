using System.Linq;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Scene cameras in a real Unity scene: which cameras count, where the views go, what is refused.</summary>
    public class SceneCamerasTests
    {
        static Camera AddCamera(string name, Transform parent, Vector3 position, Vector3 euler, float fov = 40)
        {
            var go = new GameObject(name, typeof(Camera));
            go.transform.SetParent(parent, false);
            go.transform.localPosition = position;
            go.transform.localEulerAngles = euler;
            var camera = go.GetComponent<Camera>();
            camera.fieldOfView = fov;
            return camera;
        }

        static DatasetSettings Settings()
        {
            var s = new DatasetSettings { Width = 64, Height = 32, Normalisation = NormalisationMode.None };
            s.Train.Count = 2;
            s.Val.Count = 1;
            s.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.SceneCameras, ObjectPath = "Shots" };
            return s;
        }

        [Test]
        public void EveryActiveCameraUnderTheParentIsOneViewAtItsPose()
        {
            var scene = TestScene.Open();
            try
            {
                var shots = new GameObject("Shots").transform;
                shots.position = new Vector3(1, 2, 3);
                shots.localScale = new Vector3(2, 2, 2);
                var a = AddCamera("A", shots, new Vector3(0, 0, -4), new Vector3(10, 20, 0));
                var d = AddCamera("D", a.transform, new Vector3(1, 0, 0), new Vector3(0, 90, 0));
                d.enabled = false; // a disabled Camera component still counts
                var b = AddCamera("B", shots, new Vector3(3, 1, 0), new Vector3(0, -90, 0));
                AddCamera("C", shots, Vector3.zero, Vector3.zero).gameObject.SetActive(false); // inactive: skipped

                var settings = Settings();
                SceneCameraSources.Resolve(settings);
                var cameras = settings.Test.Source.SceneCameras;
                Assert.That(settings.Test.Source.SceneProblem, Is.Null);
                Assert.That(cameras.Select(c => c.Name), Is.EqualTo(new[] { "Shots/A", "Shots/A/D", "Shots/B" }), "hierarchy order");

                var plan = CapturePlan.Build(settings, PlanTarget.AtOrigin);
                var views = plan.ViewsOf(DatasetSplit.Test).ToList();
                Assert.That(views, Has.Count.EqualTo(3));
                foreach (var (view, camera) in views.Zip(new[] { a, d, b }, (v, c) => (v, c)))
                {
                    // Unity's own camera-to-world (OpenGL axes, Unity world) relabelled by the Y/Z swap is the written matrix.
                    var m = camera.cameraToWorldMatrix;
                    for (var col = 0; col < 4; col++)
                    {
                        var output = BlenderConvention.FromUnity(new Vector3d(m[0, col], m[1, col], m[2, col]));
                        Assert.That(Vector3d.Distance(output, view.TransformMatrix.Column(col)), Is.LessThan(1e-5), camera.name + " column " + col);
                    }
                }
                Assert.That(plan.Intrinsics.CameraAngleX, Is.EqualTo(2 * System.Math.Atan(System.Math.Tan(20 * System.Math.PI / 180) * 2)).Within(1e-6),
                    "their own 40° vertical field of view at 64 × 32");
                Assert.That(a.transform.localPosition, Is.EqualTo(new Vector3(0, 0, -4)), "the scene is only read");
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void DifferentLensesOrthographicCamerasAndMissingParentsAreRefused()
        {
            var scene = TestScene.Open();
            try
            {
                var shots = new GameObject("Shots").transform;
                AddCamera("A", shots, new Vector3(0, 0, -4), Vector3.zero, 40);
                var b = AddCamera("B", shots, new Vector3(0, 0, -5), Vector3.zero, 55);

                var settings = Settings();
                SceneCameraSources.Resolve(settings);
                var problem = CapturePlan.Check(settings, PlanTarget.AtOrigin).Single();
                Assert.That(problem.Field, Is.EqualTo("splits.test.source.useCameraIntrinsics"));
                Assert.That(problem.Reason, Does.Contain("Shots/A").And.Contain("Shots/B"));

                b.orthographic = true;
                settings = Settings();
                SceneCameraSources.Resolve(settings);
                problem = CapturePlan.Check(settings, PlanTarget.AtOrigin).Single();
                Assert.That(problem.Field, Is.EqualTo("splits.test.source.parent"));
                Assert.That(problem.Reason, Does.Contain("orthographic"));

                settings = Settings();
                settings.Test.Source.ObjectPath = "Nowhere/Shots";
                SceneCameraSources.Resolve(settings);
                problem = CapturePlan.Check(settings, PlanTarget.AtOrigin).Single();
                Assert.That(problem.Field, Is.EqualTo("splits.test.source.parent"));
                Assert.That(problem.Reason, Does.Contain("names no object"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }
    }
}
