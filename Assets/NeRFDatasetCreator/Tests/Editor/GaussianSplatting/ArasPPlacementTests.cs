using System;
using System.IO;
using System.Linq;
using GaussianSplatting.Runtime;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;
using NerfDatasetCreator.Editor.Tests;
using PackageInfo = UnityEditor.PackageManager.PackageInfo;

namespace NerfDatasetCreator.Editor.GaussianSplatting.Tests
{
    /// <summary>
    /// With aras-p's Gaussian Splatting installed (this assembly exists only then): the package's camera import is still the
    /// one Documentation~/maintainers/splat-placement-editor.md reads; Place puts one undoable GaussianSplatRenderer under the
    /// source's parent with the placement's world matrix; and the package's camera slider, given the cameras.json place-splat
    /// writes, puts the main camera exactly on each dataset camera — which decides the one native step of that chain.
    /// </summary>
    [TestFixture]
    public class ArasPPlacementTests
    {
        string _root;
        string _assets;
        SceneSetup[] _setup;

        // A scene of its own replaces the open ones (restored after), so that Camera.main is the test's camera and
        // ActivateCamera never moves a camera of the user's scenes.
        [SetUp]
        public void SetUp()
        {
            for (var i = 0; i < SceneManager.sceneCount; i++)
                if (SceneManager.GetSceneAt(i).isDirty)
                    Assert.Ignore("A scene with unsaved changes is open; this test replaces the open scenes. Save or close it, then run again.");
            _setup = EditorSceneManager.GetSceneManagerSetup();
            EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            _root = Path.Combine(Path.GetTempPath(), "nerf-aras-p-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
        }

        [TearDown]
        public void TearDown()
        {
            if (_setup != null && _setup.Length > 0 && _setup.All(s => !string.IsNullOrEmpty(s.path)))
                EditorSceneManager.RestoreSceneManagerSetup(_setup);
            else
                EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            if (_assets != null) AssetDatabase.DeleteAsset(_assets);
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        /// <summary>The package's source, found through PackageInfo.FindForAssembly (UnityCsReference
        /// Modules/PackageManager/Editor/Managed/PackageInfo.cs:256 / :260) and its resolvedPath (:176 / :179).</summary>
        static string PackageFile(string relative)
        {
            var package = PackageInfo.FindForAssembly(typeof(GaussianSplatRenderer).Assembly);
            Assert.That(package, Is.Not.Null);
            Assert.That(package.name, Is.EqualTo(SplatViewers.ArasPPackage));
            return File.ReadAllText(Path.Combine(package.resolvedPath, relative));
        }

        [Test]
        public void ThePackagesCameraImportIsTheOneWeRead()
        {
            var creator = PackageFile("Editor/GaussianSplatAssetCreator.cs");
            foreach (var line in new[]
            {
                "var pos = new Vector3(jsonCam.position[0], jsonCam.position[1], jsonCam.position[2]);",
                "var axisx = new Vector3(jsonCam.rotation[0][0], jsonCam.rotation[1][0], jsonCam.rotation[2][0]);",
                "var axisy = new Vector3(jsonCam.rotation[0][1], jsonCam.rotation[1][1], jsonCam.rotation[2][1]);",
                "var axisz = new Vector3(jsonCam.rotation[0][2], jsonCam.rotation[1][2], jsonCam.rotation[2][2]);",
                "axisy *= -1;",
                "axisz *= -1;",
                "fov = 25",
                "string baseName = Path.GetFileNameWithoutExtension(FilePickerControl.PathToDisplayString(m_InputFile));",
            })
                Assert.That(creator, Does.Contain(line), "GaussianSplatAssetCreator.cs changed: re-read it (splat-placement-editor.md)");
            var renderer = PackageFile("Runtime/GaussianSplatRenderer.cs");
            Assert.That(renderer, Does.Contain("camTr.localRotation = Quaternion.LookRotation(cam.axisZ, cam.axisY);"));
            Assert.That(renderer, Does.Contain("camTr.localPosition = cam.pos;"));
        }

        [Test]
        public void PlaceMakesOneUndoableRendererUnderTheSourcesParentWithThePlacementsMatrix()
        {
            var dataset = TrainedSplatFixture.Dataset(_root);
            var model = TrainedSplatFixture.ThreeDgsModel(_root, new[] { new Vector3d(0, 0, 0) });
            var asset = AssetFor(TrainedSplatFixture.PlyOf(model), new GaussianSplatAsset.CameraInfo[0]);
            var room = new GameObject("Room");
            room.transform.SetPositionAndRotation(new Vector3(3, 0, -2), Quaternion.Euler(0, 40, 0));
            room.transform.localScale = new Vector3(2, 2, 2);
            var lego = new GameObject("Lego");
            lego.transform.SetParent(room.transform, false);

            var section = new PlaceSplatSection { Source = lego };
            section.PlaceNow(dataset, model, "3dgs", null);
            Assert.That(section.Failed, Is.False, string.Join("\n", section.Lines));
            var placed = section.Placed;
            Assert.That(placed, Is.Not.Null);
            Assert.That(placed.transform.parent, Is.SameAs(room.transform));
            Assert.That(placed.GetComponent<GaussianSplatRenderer>().m_Asset, Is.SameAs(asset));
            var expected = SplatPlacer.Place(dataset, model, "3dgs", null, writeCameras: false).ObjectToWorld;
            var actual = placed.transform.localToWorldMatrix;
            for (var i = 0; i < 16; i++) Assert.That(actual[i / 4, i % 4], Is.EqualTo(expected[i]).Within(1e-4), "object_to_world[" + i + "]");

            Undo.PerformUndo();
            Assert.That(placed == null, Is.True, "one undo removes the placed object");
        }

        [Test]
        public void TheSlidersCameraIsTheDatasetCamera()
        {
            var dataset = TrainedSplatFixture.Dataset(_root);
            var model = TrainedSplatFixture.ThreeDgsModel(_root, new[] { new Vector3d(0, 0, 0) });
            var placement = SplatPlacer.Place(dataset, model, "3dgs", null, writeCameras: true);
            var camerasJson = ArasPSplatConventions.CamerasJsonFor(placement.PlyPath);
            Assert.That(camerasJson, Is.Not.Null, "place-splat writes cameras.json where the creator looks");
            // The package's import, line for line (GaussianSplatAssetCreator.cs:1097-1113; checked above).
            var infos = JArray.Parse(File.ReadAllText(camerasJson)).Select(c =>
            {
                var cam = ArasPSplatConventions.Import(c["position"].ToObject<double[]>(), c["rotation"].ToObject<double[][]>());
                return new GaussianSplatAsset.CameraInfo
                {
                    pos = cam.Position.ToVector3(), axisX = cam.AxisX.ToVector3(), axisY = cam.AxisY.ToVector3(), axisZ = cam.AxisZ.ToVector3(), fov = (float)cam.Fov,
                };
            }).ToArray();
            var asset = ScriptableObject.CreateInstance<GaussianSplatAsset>();
            asset.Initialize(1, GaussianSplatAsset.VectorFormat.Float32, GaussianSplatAsset.VectorFormat.Float32, GaussianSplatAsset.ColorFormat.Float32x4,
                GaussianSplatAsset.SHFormat.Float32, Vector3.zero, Vector3.zero, infos);

            var local = SplatUnderParent.Local(null, Matrix4x4d.FromRowMajor(placement.ObjectToWorld), out var problem);
            Assert.That(problem, Is.Null);
            var splat = new GameObject("splat");
            splat.transform.localPosition = local.Position.ToVector3();
            splat.transform.localRotation = local.Rotation.ToQuaternion();
            splat.transform.localScale = local.Scale.ToVector3();
            var renderer = splat.AddComponent<GaussianSplatRenderer>();
            renderer.m_Asset = asset;
            var main = new GameObject("Main Camera", typeof(Camera)) { tag = "MainCamera" };
            var cameras = TransformsPoseReader.ReadFile(DatasetFolder.SplitPath(dataset, "train")).Cameras;
            Assert.That(infos.Length, Is.EqualTo(cameras.Count), "ids 0 … N−1: the train cameras");
            for (var i = 0; i < cameras.Count; i++)
            {
                renderer.ActivateCamera(i);
                var pose = cameras[i].Pose;
                Assert.That(Vector3.Distance(main.transform.position, pose.Position.ToVector3()), Is.LessThan(1e-3f), "camera " + i + " position");
                Assert.That(Vector3.Angle(main.transform.forward, pose.Rotation.Forward.ToVector3()), Is.LessThan(0.05f), "camera " + i + " forward");
                Assert.That(Vector3.Angle(main.transform.up, pose.Rotation.Up.ToVector3()), Is.LessThan(0.05f), "camera " + i + " up");
            }
            UnityEngine.Object.DestroyImmediate(asset);
        }

        /// <summary>A GaussianSplatAsset saved under the name the package's creator gives the PLY, for Place to find.</summary>
        GaussianSplatAsset AssetFor(string ply, GaussianSplatAsset.CameraInfo[] cameras)
        {
            _assets = "Assets/nerf-aras-p-" + Guid.NewGuid().ToString("N");
            AssetDatabase.CreateFolder("Assets", _assets.Substring("Assets/".Length));
            var asset = ScriptableObject.CreateInstance<GaussianSplatAsset>();
            asset.Initialize(1, GaussianSplatAsset.VectorFormat.Float32, GaussianSplatAsset.VectorFormat.Float32, GaussianSplatAsset.ColorFormat.Float32x4,
                GaussianSplatAsset.SHFormat.Float32, Vector3.zero, Vector3.zero, cameras);
            AssetDatabase.CreateAsset(asset, _assets + "/" + ArasPSplatConventions.AssetName(ply) + ".asset");
            return asset;
        }
    }
}
