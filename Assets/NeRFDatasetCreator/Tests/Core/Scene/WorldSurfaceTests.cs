using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class WorldSurfaceTests
    {
        static Matrix4x4d Scale(double x, double y, double z, Vector3d translation) =>
            Matrix4x4d.FromColumns(new Vector3d(x, 0, 0), new Vector3d(0, y, 0), new Vector3d(0, 0, z), translation);

        [Test]
        public void ADiagonalFaceKeepsItsNormalPerpendicularUnderNonUniformScale()
        {
            // The face x + y = 1 has normal (1, 1, 0)/√2. Stretched ×2 along x it becomes x/2 + y = 1, normal ∝ (1/2, 1, 0):
            // the normal matrix gives that; the matrix itself would give (2, 1, 0), tilted the wrong way.
            var local = new[] { new Vector3d(1, 0, 0), new Vector3d(0, 1, 0), new Vector3d(1, 0, 1) };
            var n = new Vector3d(1, 1, 0).Normalized();
            var m = Scale(2, 1, 1, new Vector3d(5, 6, 7));
            var mesh = WorldSurface.FromLocal(local, new[] { 0, 1, 2 }, m, new[] { n, n, n });
            var expected = new Vector3d(0.5, 1, 0).Normalized();
            Assert.That((mesh.VertexNormals[0] - expected).Length, Is.LessThan(1e-12));
            Assert.That(mesh.Vertices[0], Is.EqualTo(new Vector3d(7, 6, 7)));
            var e1 = mesh.Vertices[1] - mesh.Vertices[0];
            var e2 = mesh.Vertices[2] - mesh.Vertices[0];
            Assert.That(Vector3d.Dot(mesh.VertexNormals[0], e1), Is.EqualTo(0.0).Within(1e-12));
            Assert.That(Vector3d.Dot(mesh.VertexNormals[0], e2), Is.EqualTo(0.0).Within(1e-12));
            Assert.That(Vector3d.Dot(m.MultiplyVector(n).Normalized(), e1), Is.Not.EqualTo(0.0).Within(1e-3), "the naive transform is wrong");
        }

        [Test]
        public void RotationsMoveNormalsWithTheSurfaceAndMirrorsKeepThemOutward()
        {
            // 90° about Unity's y: +x → −z.
            var rotation = Matrix4x4d.FromColumns(new Vector3d(0, 0, -1), new Vector3d(0, 1, 0), new Vector3d(1, 0, 0), Vector3d.Zero);
            Assert.That((WorldSurface.TransformNormal(rotation, new Vector3d(1, 0, 0)) - new Vector3d(0, 0, -1)).Length, Is.LessThan(1e-15));
            // A mirror in x sends the face at x = +1 to x = −1, whose outward normal is −x.
            var mirror = Scale(-1, 1, 1, Vector3d.Zero);
            Assert.That(WorldSurface.TransformNormal(mirror, new Vector3d(1, 0, 0)), Is.EqualTo(new Vector3d(-1, 0, 0)));
            Assert.That(WorldSurface.TransformNormal(Scale(0, 1, 1, Vector3d.Zero), new Vector3d(1, 0, 0)), Is.EqualTo(Vector3d.Zero), "degenerate");
        }

        [Test]
        public void ColoursAndTrianglesPassThrough()
        {
            var local = new[] { Vector3d.Zero, Vector3d.UnitX, Vector3d.UnitY };
            var colours = new[] { new Vector3d(1, 0, 0) };
            var mesh = WorldSurface.FromLocal(local, new[] { 0, 1, 2 }, Scale(3, 3, 3, Vector3d.Zero), triangleColors: colours, name: "tri");
            Assert.That(mesh.TriangleArea(0), Is.EqualTo(4.5).Within(1e-12), "½·3·3");
            Assert.That(mesh.TriangleColors, Is.SameAs(colours));
            Assert.That(mesh.VertexNormals, Is.Null);
            Assert.That(mesh.Name, Is.EqualTo("tri"));
        }
    }
}
