using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SplatUnderParentTests
    {
        // The issue-34 placement for s = 2, c = (1, 2, 3): position B·c = (1, 3, 2), Euler(90, 0, 0), scale (½, ½, −½).
        // Rx(90°) takes y to z and z to −y, so the linear part is Rx(90)·diag(½, ½, −½) = ½·B, B(x, y, z) = (x, z, y).
        static readonly Matrix4x4d Placement = Matrix4x4d.FromColumns(
            new Vector3d(0.5, 0, 0), new Vector3d(0, 0, 0.5), new Vector3d(0, 0.5, 0), new Vector3d(1, 3, 2));

        static Matrix4x4d Trs(Vector3d t, Quaterniond q, Vector3d s) =>
            Matrix4x4d.FromColumns(q.Right * s.X, q.Up * s.Y, q.Forward * s.Z, t);

        static void AssertSame(Matrix4x4d a, Matrix4x4d b)
        {
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    Assert.That(a[r, c], Is.EqualTo(b[r, c]).Within(1e-12), "[" + r + ", " + c + "]");
        }

        [Test]
        public void WithoutAParentTheReflectionGoesIntoZsScale()
        {
            var local = SplatUnderParent.Local(null, Placement, out var problem);
            Assert.That(problem, Is.Null);
            Assert.That(local.Position, Is.EqualTo(new Vector3d(1, 3, 2)));
            Assert.That(local.Scale, Is.EqualTo(new Vector3d(0.5, 0.5, -0.5)));
            var h = Math.Sqrt(0.5);
            Assert.That(local.Rotation.X, Is.EqualTo(h).Within(1e-12), "Rx(90°) = (sin 45°, 0, 0, cos 45°)");
            Assert.That(local.Rotation.W, Is.EqualTo(h).Within(1e-12));
            AssertSame(Trs(local.Position, local.Rotation, local.Scale), Placement);
        }

        [Test]
        public void UnderAMovedTurnedScaledParentTheWorldMatrixIsKept()
        {
            var parent = Trs(new Vector3d(10, -1, 4), Quaterniond.AngleAxis(30, new Vector3d(0, 1, 0)), new Vector3d(2, 2, 2));
            // The parent's worldToLocalMatrix, built independently: S⁻¹·Rᵀ·T⁻¹.
            var q = Quaterniond.AngleAxis(30, new Vector3d(0, 1, 0));
            var inverseRotation = new Quaterniond(-q.X, -q.Y, -q.Z, q.W);
            var worldToLocal = Trs(Vector3d.Zero, Quaterniond.Identity, new Vector3d(0.5, 0.5, 0.5))
                               * Trs(Vector3d.Zero, inverseRotation, new Vector3d(1, 1, 1))
                               * Trs(new Vector3d(-10, 1, -4), Quaterniond.Identity, new Vector3d(1, 1, 1));
            var local = SplatUnderParent.Local(worldToLocal, Placement, out var problem);
            Assert.That(problem, Is.Null);
            Assert.That(local.Scale.Z, Is.LessThan(0));
            Assert.That(local.Scale.X, Is.EqualTo(0.25).Within(1e-12));
            AssertSame(parent * Trs(local.Position, local.Rotation, local.Scale), Placement);
        }

        [Test]
        public void AnUnevenlyScaledTurnedParentIsRefusedWithTheReason()
        {
            var q = Quaterniond.AngleAxis(45, new Vector3d(0, 0, 1));
            var inverseRotation = new Quaterniond(-q.X, -q.Y, -q.Z, q.W);
            var worldToLocal = Trs(Vector3d.Zero, Quaterniond.Identity, new Vector3d(1, 0.5, 1)) * Trs(Vector3d.Zero, inverseRotation, new Vector3d(1, 1, 1));
            var local = SplatUnderParent.Local(worldToLocal, Placement, out var problem);
            Assert.That(local, Is.Null);
            Assert.That(problem, Does.Contain("sheared"));
        }
    }
}
