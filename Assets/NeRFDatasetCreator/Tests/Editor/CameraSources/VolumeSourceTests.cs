using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>A volume source in a real Unity scene: a box object, a BoxCollider wall across it, no camera inside the wall.</summary>
    public class VolumeSourceTests
    {
        static DatasetSettings Settings(string box)
        {
            var s = new DatasetSettings { Width = 64, Height = 32, Normalisation = NormalisationMode.None };
            s.Train.Count = 200;
            s.Train.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = box, Look = VolumeLook.Sphere, Clearance = 0.2 };
            s.Val.Count = 1;
            s.Test.Count = 1;
            return s;
        }

        [Test]
        public void NoCameraIsPlacedInsideATurnedBoxColliderWall()
        {
            var scene = TestScene.Open();
            try
            {
                Assume.That(SceneManager.sceneCount, Is.EqualTo(1), "colliders of other open scenes would be obstacles too");
                var volume = new GameObject("CaptureVolume").transform;
                volume.position = new Vector3(0, 1, 0);
                volume.localScale = new Vector3(10, 2, 10);
                // The wall: a scaled, turned BoxCollider with an offset centre, as a wall built from a Cube primitive would be.
                var wall = new GameObject("Wall", typeof(BoxCollider));
                wall.transform.position = new Vector3(0.5f, 1, 0);
                wall.transform.rotation = Quaternion.Euler(0, 30, 0);
                wall.transform.localScale = new Vector3(2, 4, 12);
                var collider = wall.GetComponent<BoxCollider>();
                collider.center = new Vector3(-0.25f, 0, 0);
                collider.size = new Vector3(0.5f, 1, 1);
                var trigger = new GameObject("Trigger", typeof(BoxCollider));
                trigger.GetComponent<BoxCollider>().isTrigger = true; // not solid: never an obstacle
                trigger.transform.localScale = new Vector3(100, 100, 100);

                var settings = Settings("CaptureVolume");
                SceneCameraSources.Resolve(settings);
                Assert.That(settings.Train.Source.SceneProblem, Is.Null);
                Assert.That(settings.Train.Source.Volume.Obstacles.Select(o => o.Name), Is.EqualTo(new[] { "Wall" }));

                var plan = CapturePlan.Build(settings, PlanTarget.AtOrigin);
                var views = plan.ViewsOf(DatasetSplit.Train).ToList();
                Assert.That(views, Has.Count.EqualTo(200));
                Physics.SyncTransforms();
                foreach (var view in views)
                {
                    var p = new Vector3((float)view.Pose.Position.X, (float)view.Pose.Position.Y, (float)view.Pose.Position.Z);
                    // Unity's own answer: the point in the wall's local space, against the collider's box grown by the clearance / scale.
                    var local = wall.transform.InverseTransformPoint(p) - collider.center;
                    var inside = Mathf.Abs(local.x) <= collider.size.x / 2 + 0.2f / 2 && Mathf.Abs(local.y) <= collider.size.y / 2 + 0.2f / 4 && Mathf.Abs(local.z) <= collider.size.z / 2 + 0.2f / 12;
                    Assert.That(inside, Is.False, "camera at " + p + " is inside the wall or its clearance");
                    Assert.That(Physics.OverlapSphere(p, 0.01f).Where(c => !c.isTrigger), Is.Empty, "PhysX agrees: no solid collider at " + p);
                    Assert.That(Mathf.Abs(p.x) <= 5 && p.y >= 0 && p.y <= 2 && Mathf.Abs(p.z) <= 5, Is.True, "inside the capture box: " + p);
                }
                Assert.That(plan.Warnings.Single(w => w.Field == "splits.train.source.box").Reason, Does.Contain("Wall"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void ThePreviewReadsObstaclesFromACacheAndAPreparedCaptureReadsThemAfresh()
        {
            var scene = TestScene.Open();
            try
            {
                Assume.That(SceneManager.sceneCount, Is.EqualTo(1), "colliders of other open scenes would be obstacles too");
                var wall = new GameObject("Wall", typeof(BoxCollider));
                VolumeSource.ClearCache();
                Assert.That(VolumeSource.Obstacles(null).Single().Centre.X, Is.EqualTo(0).Within(1e-6));
                // ObjectChangeEvents are published after this editor update, so within it the cache still answers.
                wall.transform.position = new Vector3(3, 0, 0);
                Assert.That(VolumeSource.Obstacles(null).Single().Centre.X, Is.EqualTo(0).Within(1e-6), "served from the cache");
                DatasetCapture.Prepare(Settings("CaptureVolume"), null, System.IO.Path.GetTempPath());
                Assert.That(VolumeSource.Obstacles(null).Single().Centre.X, Is.EqualTo(3).Within(1e-6), "Prepare cleared the cache");
            }
            finally
            {
                TestScene.Close(scene);
                VolumeSource.ClearCache();
            }
        }

        [Test]
        public void APathsWaypointsAreItsChildrenInHierarchyOrderAndItsCamerasFollowThem()
        {
            var scene = TestScene.Open();
            try
            {
                new GameObject("CaptureVolume").transform.localScale = new Vector3(20, 4, 20);
                var path = new GameObject("Flythrough").transform;
                path.position = new Vector3(0, 1, 0);
                foreach (var x in new[] { -3f, 2f, 5f }) // children in this order, whatever their names
                {
                    var w = new GameObject("W" + (5 - x)).transform;
                    w.SetParent(path, false);
                    w.localPosition = new Vector3(x, 0, 0);
                }
                path.GetChild(1).gameObject.SetActive(false); // a disabled marker still marks the path

                var settings = Settings("CaptureVolume");
                settings.Train.Count = 9;
                settings.Train.Source.Look = VolumeLook.Path;
                settings.Train.Source.PathObject = "Flythrough";
                settings.Train.Source.JitterDegrees = 0;
                SceneCameraSources.Resolve(settings);
                Assert.That(settings.Train.Source.SceneProblem, Is.Null);
                Assert.That(settings.Train.Source.Volume.Waypoints.Select(w => w.X), Is.EqualTo(new[] { -3.0, 2, 5 }).Within(1e-6));
                Assert.That(settings.Train.Source.Volume.Waypoints.Select(w => w.Y), Is.All.EqualTo(1).Within(1e-6), "world positions");

                var views = CapturePlan.Build(settings, PlanTarget.AtOrigin).ViewsOf(DatasetSplit.Train).ToList();
                Assert.That(views.Select(v => v.Pose.Position.X), Is.EqualTo(new[] { -3.0, -2, -1, 0, 1, 2, 3, 4, 5 }).Within(1e-5));
                var forward = new Quaternion((float)views[4].Pose.Rotation.X, (float)views[4].Pose.Rotation.Y, (float)views[4].Pose.Rotation.Z, (float)views[4].Pose.Rotation.W) * Vector3.forward;
                Assert.That(Vector3.Angle(forward, Vector3.right), Is.LessThan(0.01f), "looking along the path");

                settings.Train.Source.PathObject = "Missing";
                SceneCameraSources.Resolve(settings);
                Assert.That(settings.Train.Source.SceneProblem.Field, Is.EqualTo("splits.train.source.waypoints"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void AnEnvironmentsSurfaceIsEveryActiveRootsMeshes()
        {
            var scene = TestScene.Open();
            try
            {
                Assume.That(SceneManager.sceneCount, Is.EqualTo(1), "meshes of other open scenes would be sampled too");
                var floor = GameObject.CreatePrimitive(PrimitiveType.Cube);
                floor.name = "Floor";
                floor.transform.position = new Vector3(0, -1, 0);
                var crate = GameObject.CreatePrimitive(PrimitiveType.Cube);
                crate.name = "Crate";
                crate.transform.position = new Vector3(3, 0, 0);
                var hidden = GameObject.CreatePrimitive(PrimitiveType.Cube);
                hidden.SetActive(false); // inactive roots are neither rendered nor sampled

                var warnings = new List<ValidationProblem>();
                var meshes = TargetSurface.CollectScene(warnings);
                Assert.That(warnings, Is.Empty);
                // Each cube: 12 triangles; world positions, so the crate's vertices are around x = 3.
                Assert.That(meshes, Has.Count.EqualTo(2));
                Assert.That(meshes.Sum(m => m.TriangleCount), Is.EqualTo(24));
                Assert.That(meshes.SelectMany(m => m.Vertices).Max(v => v.X), Is.EqualTo(3.5).Within(1e-6));
                Assert.That(meshes.SelectMany(m => m.Vertices).Min(v => v.Y), Is.EqualTo(-1.5).Within(1e-6));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void AMissingBoxObjectIsReportedByItsField()
        {
            var scene = TestScene.Open();
            try
            {
                var settings = Settings("Nowhere");
                SceneCameraSources.Resolve(settings);
                Assert.That(settings.Train.Source.SceneProblem.Field, Is.EqualTo("splits.train.source.box"));
                Assert.That(CapturePlan.Check(settings, PlanTarget.AtOrigin).Single().Reason, Does.Contain("names no object"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }
    }
}
