using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// TargetSurface on Unity's primitive cube: 24 vertices (4 per face, so each face has its own normals), 12
    /// triangles, side 1. Its surface area is 6; scaled by (2, 1, 1) it is 2·(1·1) + 4·(2·1) = 10, and the face
    /// normals stay the axes (the x faces keep ±x: a stretched cube's faces do not tilt).
    /// </summary>
    [TestFixture]
    public class TargetSurfaceTests
    {
        GameObject _cube;

        [SetUp]
        public void CreateCube() => _cube = GameObject.CreatePrimitive(PrimitiveType.Cube);

        [TearDown]
        public void DestroyCube()
        {
            if (_cube != null) UnityEngine.Object.DestroyImmediate(_cube);
        }

        static double Area(SurfaceMesh mesh) => Enumerable.Range(0, mesh.TriangleCount).Sum(t => mesh.TriangleArea(t));

        [Test]
        public void TheUnitCubeHas24VerticesAnd12TrianglesOfTotalAreaSix()
        {
            var warnings = new List<ValidationProblem>();
            var meshes = TargetSurface.Collect(_cube, warnings);
            Assert.That(warnings, Is.Empty);
            Assert.That(meshes, Has.Count.EqualTo(1));
            Assert.That(meshes[0].Vertices, Has.Count.EqualTo(24));
            Assert.That(meshes[0].TriangleCount, Is.EqualTo(12));
            Assert.That(Area(meshes[0]), Is.EqualTo(6.0).Within(1e-5));
            Assert.That(meshes[0].TriangleColors, Has.Count.EqualTo(12), "no vertex colours: the material's colour per triangle");
        }

        [Test]
        public void ANonUniformScaleStretchesTheAreaAndKeepsTheNormalsOnTheAxes()
        {
            _cube.transform.position = new Vector3(3, -1, 2);
            _cube.transform.localScale = new Vector3(2, 1, 1);
            var mesh = TargetSurface.Collect(_cube, new List<ValidationProblem>()).Single();
            Assert.That(Area(mesh), Is.EqualTo(10.0).Within(1e-5));
            Assert.That(mesh.Vertices.Min(v => v.X), Is.EqualTo(2.0).Within(1e-6));
            Assert.That(mesh.Vertices.Max(v => v.X), Is.EqualTo(4.0).Within(1e-6));
            foreach (var n in mesh.VertexNormals)
            {
                Assert.That(n.Length, Is.EqualTo(1.0).Within(1e-6));
                var largest = Math.Max(Math.Abs(n.X), Math.Max(Math.Abs(n.Y), Math.Abs(n.Z)));
                Assert.That(largest, Is.EqualTo(1.0).Within(1e-6), "axis-aligned");
            }
            // Every normal points away from the cube's centre (outward).
            for (var i = 0; i < mesh.Vertices.Count; i++)
                Assert.That(Vector3d.Dot(mesh.VertexNormals[i], mesh.Vertices[i] - new Vector3d(3, -1, 2)), Is.GreaterThan(0));
        }

        [Test]
        public void DisabledRenderersAndInactiveChildrenAreLeftOut()
        {
            var child = GameObject.CreatePrimitive(PrimitiveType.Cube);
            child.transform.SetParent(_cube.transform, false);
            Assert.That(TargetSurface.Collect(_cube, new List<ValidationProblem>()), Has.Count.EqualTo(2));
            child.SetActive(false);
            Assert.That(TargetSurface.Collect(_cube, new List<ValidationProblem>()), Has.Count.EqualTo(1));
            _cube.GetComponent<MeshRenderer>().enabled = false;
            Assert.That(TargetSurface.Collect(_cube, new List<ValidationProblem>()), Is.Empty);
        }

        [Test]
        public void SampledPointsLieOnTheCube()
        {
            var meshes = TargetSurface.Collect(_cube, new List<ValidationProblem>());
            var points = SurfaceSampler.Sample(meshes, 200, 1);
            foreach (var p in points)
            {
                var largest = Math.Max(Math.Abs(p.Position.X), Math.Max(Math.Abs(p.Position.Y), Math.Abs(p.Position.Z)));
                Assert.That(largest, Is.EqualTo(0.5).Within(1e-5), "on a face of the unit cube");
            }
        }
    }
}
