using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Place trained splat (issue 34) with no splat viewer: the placement is shown with the package to install and nothing is
    /// put in the scene; refusals name the field and the fix; the source/splat toggle is one undoable step; View from camera i
    /// puts the Scene view's camera on the dataset camera with its vertical field of view.
    /// </summary>
    [TestFixture]
    public class PlaceSplatTests
    {
        string _root;
        ISplatViewer _viewer;
        Scene _scene;

        [SetUp]
        public void SetUp()
        {
            _root = Path.Combine(Path.GetTempPath(), "nerf-place-splat-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
            _viewer = SplatViewers.Installed;
            _scene = TestScene.Open();
        }

        [TearDown]
        public void TearDown()
        {
            SplatViewers.Register(_viewer);
            TestScene.Close(_scene);
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        [Test]
        public void WithoutAViewerTheTransformIsShownWithThePackageToInstall()
        {
            SplatViewers.Register(null);
            var dataset = TrainedSplatFixture.Dataset(_root);
            var model = TrainedSplatFixture.ThreeDgsModel(_root, new[] { new Vector3d(0, 0, 0), new Vector3d(0.1, 0.2, 0.3) });
            var objects = _scene.rootCount;
            var section = new PlaceSplatSection();
            section.PlaceNow(dataset, model, null, null);

            Assert.That(section.Failed, Is.False, string.Join("\n", section.Lines));
            Assert.That(section.Lines, Has.Some.StartsWith("Position: ("));
            Assert.That(section.Lines, Has.Some.Contains(SplatViewers.ArasPGitUrl));
            Assert.That(section.Placed, Is.Null);
            Assert.That(_scene.rootCount, Is.EqualTo(objects), "nothing is put in the scene");
        }

        [Test]
        public void WithoutASourcePickedTheDatasetsTargetIsFoundByItsPath()
        {
            SplatViewers.Register(null);
            var dataset = TrainedSplatFixture.Dataset(_root);
            var config = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(Path.Combine(dataset, "dataset_config.json")));
            var name = "Lego " + Guid.NewGuid().ToString("N"); // unique, whatever else the loaded scenes hold
            config["settings"]["target"] = "Props/" + name;
            File.WriteAllText(Path.Combine(dataset, "dataset_config.json"), config.ToString());
            var props = new GameObject("Props");
            var lego = new GameObject(name).transform;
            lego.SetParent(props.transform, false);
            var model = TrainedSplatFixture.ThreeDgsModel(_root, new[] { new Vector3d(0, 0, 0) });
            var section = new PlaceSplatSection();
            section.PlaceNow(dataset, model, null, null);
            Assert.That(section.Source, Is.SameAs(lego.gameObject));
            Assert.That(section.Lines, Has.Some.StartsWith("Source object: Props/Lego "));
        }

        [Test]
        public void ThePlacementTakesTheDatasetsCamerasToWhereTheyWereInUnity()
        {
            // The 3DGS splat is in the dataset's frame, so object_to_world must take each train camera's centre (as
            // transforms_train.json writes it) to the camera's Unity position (TransformsPoseReader undoes the normalisation).
            var dataset = TrainedSplatFixture.Dataset(_root);
            var model = TrainedSplatFixture.ThreeDgsModel(_root, new[] { new Vector3d(0, 0, 0) });
            var placement = SplatPlacer.Place(dataset, model, null, null, writeCameras: false);
            Assert.That(placement.PlyPath, Is.EqualTo(Path.GetFullPath(TrainedSplatFixture.PlyOf(model))), "the highest iteration by number");
            var m = Matrix4x4d.FromRowMajor(placement.ObjectToWorld);
            foreach (var camera in TransformsPoseReader.ReadFile(DatasetFolder.SplitPath(dataset, "train")).Cameras)
                Assert.That(Vector3d.Distance(m.MultiplyPoint(camera.FileCameraToWorld.Translation), camera.Pose.Position), Is.LessThan(1e-5), camera.Name);
        }

        [Test]
        public void AModelFolderWithNothingTrainedIsRefusedAndNothingIsPlaced()
        {
            var dataset = TrainedSplatFixture.Dataset(_root);
            var empty = Path.Combine(_root, "empty");
            Directory.CreateDirectory(empty);
            var section = new PlaceSplatSection();
            section.PlaceNow(dataset, empty, null, null);
            Assert.That(section.Failed, Is.True);
            Assert.That(section.Lines, Is.Not.Empty);
            Assert.That(section.Placed, Is.Null);
            var problem = new ValidationProblem("--model", empty, "holds no trained model.", "Give the trainer's output folder.");
            Assert.That(PlaceSplatSection.Refusal(new InvalidParameterException(new[] { problem })), Is.EqualTo(new[] { problem.ToString() }));
        }

        [Test]
        public void TheToggleShowsOneOfTheTwoAndUndoBringsBothBack()
        {
            var source = new GameObject("Lego");
            var splat = new GameObject("Lego (splat)");
            var section = new PlaceSplatSection { Source = source, Placed = splat };
            section.ShowSplat(true);
            Assert.That(splat.activeSelf, Is.True);
            Assert.That(source.activeSelf, Is.False);
            section.ShowSplat(false);
            Assert.That(source.activeSelf, Is.True);
            Assert.That(splat.activeSelf, Is.False);
            Undo.PerformUndo();
            Assert.That(source.activeSelf, Is.False, "undo of Show source");
            Assert.That(splat.activeSelf, Is.True);
        }

        [Test]
        public void ViewFromCameraPutsTheSceneViewCameraOnTheDatasetCamera()
        {
            var view = SceneView.lastActiveSceneView;
            if (view == null) Assert.Ignore("No Scene view is open (batch mode): nothing to align.");
            var dataset = TrainedSplatFixture.Dataset(_root);
            var camera = TransformsPoseReader.ReadFile(DatasetFolder.SplitPath(dataset, "train")).Cameras[2];
            var section = new PlaceSplatSection();
            // The user's view is put back afterwards.
            Vector3 pivot = view.pivot; Quaternion rotation = view.rotation; float size = view.size, fov = view.cameraSettings.fieldOfView;
            bool ortho = view.orthographic, in2D = view.in2DMode;
            try { ViewFromCameraChecks(view, section, dataset, camera); }
            finally
            {
                view.in2DMode = in2D;
                view.cameraSettings.fieldOfView = fov;
                view.LookAt(pivot, rotation, size, ortho, true);
            }
        }

        static void ViewFromCameraChecks(SceneView view, PlaceSplatSection section, string dataset, ImportedCamera camera)
        {
            section.ViewFromCamera(dataset, 2);
            Assert.That(section.Failed, Is.False, string.Join("\n", section.Lines));
            // SceneView's camera is placed at pivot + rotation·(0, 0, −cameraDistance) when it draws (SceneView.cs:3123 / :3514).
            var expected = camera.Pose.Position.ToVector3();
            var position = view.pivot + view.rotation * new Vector3(0, 0, -view.cameraDistance);
            Assert.That(Vector3.Distance(position, expected), Is.LessThan(1e-3f * Mathf.Max(1, expected.magnitude)));
            Assert.That(Quaternion.Angle(view.rotation, camera.Pose.Rotation.ToQuaternion()), Is.LessThan(0.01f));
            Assert.That(view.orthographic, Is.False);
            var vertical = 2 * Math.Atan(camera.Intrinsics.Height / (2 * camera.Intrinsics.FlY)) * 180 / Math.PI;
            var setting = view.camera.aspect < 1
                ? 2 * Math.Atan(view.camera.aspect * Math.Tan(vertical * Math.PI / 360)) * 180 / Math.PI
                : vertical;
            Assert.That(view.cameraSettings.fieldOfView, Is.EqualTo(setting).Within(1e-3));
            Assert.That(section.Lines[0], Does.StartWith("Scene view on train camera 2"));
        }

        [Test]
        public void ViewFromACameraTheDatasetDoesNotHaveSaysHowManyItHas()
        {
            var dataset = TrainedSplatFixture.Dataset(_root);
            var count = TransformsPoseReader.ReadFile(DatasetFolder.SplitPath(dataset, "train")).Cameras.Count;
            var section = new PlaceSplatSection();
            section.ViewFromCamera(dataset, count);
            Assert.That(section.Failed, Is.True);
            Assert.That(section.Lines[0], Is.EqualTo("Camera " + count + " does not exist: the dataset has " + count + " train cameras (0 … " + (count - 1) + ")."));
        }
    }
}
