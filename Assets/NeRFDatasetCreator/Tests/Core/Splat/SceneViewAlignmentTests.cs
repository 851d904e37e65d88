using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SceneViewAlignmentTests
    {
        static readonly UnityPose AtOneTwoThree = new UnityPose(new Vector3d(1, 2, 3), Quaterniond.Identity);

        // 800×600, fl_y = 600: tan(v/2) = 300/600 = 0.5, v = 2·atan(0.5) = 53.130102°.
        static ImportedIntrinsics Pinhole(double fx = 600, double fy = 600, double cx = 400, double cy = 300) =>
            new ImportedIntrinsics(2 * Math.Atan(400 / fx), 800, 600, fx, fy, cx, cy);

        // SceneView.GetVerticalFOV (2022.3.76f1 SceneView.cs:3229-3239), restated: what the Scene view's camera gets.
        static double SceneViewVertical(double fov, double aspect) =>
            2 * Math.Atan(Math.Tan(fov * Math.PI / 360) * (aspect < 1 ? 1 / aspect : 1)) * 180 / Math.PI;

        [Test]
        public void AWideSceneViewTakesTheVerticalFieldAndPutsItsCameraOnTheDatasetCamera()
        {
            var a = SceneViewAlignment.For(AtOneTwoThree, Pinhole(), 800.0 / 600, 2);
            Assert.That(a.VerticalFovDegrees, Is.EqualTo(53.13010235415598).Within(1e-9));
            Assert.That(a.FieldOfView, Is.EqualTo(53.13010235415598).Within(1e-9));
            // size = d·sin(fov/2) = 2·0.5/√1.25 = 0.894427191.
            Assert.That(a.Size, Is.EqualTo(0.8944271909999159).Within(1e-12));
            Assert.That(a.Pivot, Is.EqualTo(new Vector3d(1, 2, 5)), "2 in front along +Z");
            // The Scene view's camera: pivot + rotation·(0, 0, −size / sin(fov/2)) (SceneView.cs:3123, :951-967).
            var distance = a.Size / Math.Sin(a.FieldOfView * Math.PI / 360);
            var camera = a.Pivot + a.Rotation.Rotate(new Vector3d(0, 0, -distance));
            Assert.That(Vector3d.Distance(camera, AtOneTwoThree.Position), Is.LessThan(1e-12));
            Assert.That(a.Inexact, Is.Empty, "centred, square pixels, same aspect");
        }

        [Test]
        public void ATallSceneViewTakesTheHorizontalSettingThatGivesTheSameVerticalField()
        {
            var a = SceneViewAlignment.For(AtOneTwoThree, Pinhole(), 0.5, 1);
            // tan(F/2) = 0.5·0.5: F = 2·atan(0.25) = 28.072487°.
            Assert.That(a.FieldOfView, Is.EqualTo(28.072486935852954).Within(1e-9));
            Assert.That(SceneViewVertical(a.FieldOfView, 0.5), Is.EqualTo(a.VerticalFovDegrees).Within(1e-9));
            var distance = a.Size / Math.Sin(a.FieldOfView * Math.PI / 360);
            Assert.That(distance, Is.EqualTo(1).Within(1e-12));
            Assert.That(a.Inexact, Has.Some.Contains("0.5:1"));
        }

        [Test]
        public void WhatTheSceneViewCannotShowIsNamed()
        {
            var a = SceneViewAlignment.For(AtOneTwoThree, Pinhole(fx: 610, cx: 410, cy: 290), 800.0 / 600, 1);
            Assert.That(a.Inexact, Has.Some.Contains("principal point is off centre by (10, -10) px"));
            Assert.That(a.Inexact, Has.Some.Contains("fl_x (610) differs from fl_y (600)"));
            Assert.That(a.Inexact, Has.None.Contains("sides"), "same aspect");
            var narrow = SceneViewAlignment.For(AtOneTwoThree, Pinhole(fx: 20000, fy: 20000), 800.0 / 600, 1);
            Assert.That(narrow.Inexact, Has.Some.Contains("orthographic"), "2·atan(300/20000) = 1.72°");
        }

        [Test]
        public void ACameraWithoutIntrinsicsIsRefusedByName()
        {
            var e = Assert.Throws<InvalidParameterException>(() => SceneViewAlignment.For(AtOneTwoThree, ImportedIntrinsics.AngleOnly(0.7), 1.5, 1));
            Assert.That(e.Problems[0].Field, Is.EqualTo("camera intrinsics"));
            Assert.Throws<ArgumentOutOfRangeException>(() => SceneViewAlignment.For(AtOneTwoThree, Pinhole(), 1.5, 0));
        }
    }
}
