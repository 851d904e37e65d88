using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Exact flow on analytic motion (issue 37): a plane moved rigidly and seen by two cameras (flow from the closed-form
    /// ray–plane intersection, the rigid motion and the cameras' matrices), occlusion at a known boundary, forward then
    /// backward flow returning to the pixel, and a rigid sphere whose hidden points are the back-facing ones.
    /// </summary>
    public class SurfaceFlowTests
    {
        static readonly Vector3d Axis = new Vector3d(0.3, -0.2, 1);
        const double Degrees = 9;
        static readonly Vector3d Move = new Vector3d(0.12, -0.07, 0.05);

        static SurfaceFlow MovingPlane(out List<double> vertices, out int[] triangles)
        {
            vertices = new List<double>();
            var list = new List<int>();
            FlowTestScenes.Grid(6, 0, vertices, list);
            triangles = list.ToArray();
            return new SurfaceFlow(vertices.ToArray(), FlowTestScenes.Rigid(vertices, Axis, Degrees, Move), triangles);
        }

        [Test]
        public void PlaneFlowEqualsTheClosedFormToAMillionthOfAPixel()
        {
            var flow = MovingPlane(out _, out _);
            var from = FlowTestScenes.Camera(new Vector3d(0.2, -2.5, 2), new Vector3d(0, 0, 0), out var fromMatrix);
            var to = FlowTestScenes.Camera(new Vector3d(0.5, -2.3, 2.2), new Vector3d(0.05, 0, 0), out var toMatrix);
            var field = flow.Image(from, to);
            int checkedPixels = 0, none = 0;
            for (var v = 0; v < from.Height; v++)
                for (var u = 0; u < from.Width; u++)
                {
                    double x = u + 0.5, y = v + 0.5;
                    // The ray through the pixel centre meets z = 0 at o + s·d, s = −o_z / d_z.
                    var d = fromMatrix.MultiplyVector(new Vector3d((x - 32) / 60, -(y - 24) / 60, -1));
                    var o = fromMatrix.Translation;
                    var p = o + d * (-o.Z / d.Z);
                    var state = (FlowState)field.State[v * from.Width + u];
                    if (Math.Abs(p.X) > 1 || Math.Abs(p.Y) > 1)
                    {
                        // Off the plane (away from its border by a margin the mesh cannot blur): no surface.
                        if (Math.Abs(p.X) > 1.001 || Math.Abs(p.Y) > 1.001) { Assert.That(state, Is.EqualTo(FlowState.NoSurface), u + "," + v); none++; }
                        continue;
                    }
                    if (Math.Abs(p.X) > 0.999 || Math.Abs(p.Y) > 0.999) continue;
                    var q = FlowTestScenes.Rotate(p, Axis, Degrees) + Move;
                    Assert.That(FlowTestScenes.Project(toMatrix, 60, 32, 24, q, out var x2, out var y2), Is.True);
                    Assert.That((double)field.Flow[2 * (v * from.Width + u)], Is.EqualTo(x2 - x).Within(1e-4), "Δx " + u + "," + v); // float32 file precision
                    Assert.That(flow.At(from, to, x, y, out var s), Is.Not.EqualTo(FlowState.NoSurface));
                    Assert.That(s.Dx, Is.EqualTo(x2 - x).Within(1e-6), "Δx " + u + "," + v);
                    Assert.That(s.Dy, Is.EqualTo(y2 - y).Within(1e-6), "Δy " + u + "," + v);
                    Assert.That(s.Qx - s.Px, Is.EqualTo(q.X - p.X).Within(1e-9));
                    Assert.That(s.Qz - s.Pz, Is.EqualTo(q.Z - p.Z).Within(1e-9));
                    // Nothing else is in the scene: every point inside the other image is visible.
                    Assert.That(state, Is.EqualTo(to.Inside(x2, y2) ? FlowState.Visible : FlowState.OutsideImage), u + "," + v);
                    checkedPixels++;
                }
            Assert.That(checkedPixels, Is.GreaterThan(800));
            Assert.That(none, Is.GreaterThan(50));
        }

        [Test]
        public void ForwardThenBackwardReturnsToThePixel()
        {
            var forward = MovingPlane(out var vertices, out var triangles);
            var backward = new SurfaceFlow(FlowTestScenes.Rigid(vertices, Axis, Degrees, Move), vertices.ToArray(), triangles);
            var from = FlowTestScenes.Camera(new Vector3d(0.2, -2.5, 2), new Vector3d(0, 0, 0));
            var to = FlowTestScenes.Camera(new Vector3d(0.5, -2.3, 2.2), new Vector3d(0.05, 0, 0));
            var visible = 0;
            for (var v = 0; v < from.Height; v += 3)
                for (var u = 0; u < from.Width; u += 3)
                {
                    double x = u + 0.5, y = v + 0.5;
                    if (forward.At(from, to, x, y, out var f) != FlowState.Visible) continue;
                    Assert.That(backward.At(to, from, x + f.Dx, y + f.Dy, out var b), Is.EqualTo(FlowState.Visible));
                    Assert.That(f.Dx + b.Dx, Is.EqualTo(0).Within(1e-7));
                    Assert.That(f.Dy + b.Dy, Is.EqualTo(0).Within(1e-7));
                    visible++;
                }
            Assert.That(visible, Is.GreaterThan(100));
        }

        /// <summary>
        /// A camera straight above x = 0 looks down on a plane at z = 0 moving +0.5 in x, under a static strip at z = 0.5
        /// over x ≥ 0. The strip's edge plane x = 0 contains the camera, so on the moving plane exactly the points at
        /// x &gt; 0 are hidden at t′: a pixel showing the plane is hidden iff its point had x &gt; −0.5 at t.
        /// </summary>
        [Test]
        public void OcclusionByAStaticStripFollowsTheKnownBoundary()
        {
            var vertices = new List<double>();
            var triangles = new List<int>();
            FlowTestScenes.Grid(8, 0, vertices, triangles, -2, 2);
            var planeVertices = vertices.Count;
            FlowTestScenes.Grid(4, 0.5, vertices, triangles, 0, 3);
            var moved = vertices.ToArray();
            for (var i = 0; i < planeVertices; i += 3) moved[i] += 0.5;
            var flow = new SurfaceFlow(vertices.ToArray(), moved, triangles.ToArray());
            var camera = FlowTestScenes.Camera(new Vector3d(0, 0, 3), new Vector3d(0, 0, 0), out var m, 80, 60, 50);
            int hidden = 0, visible = 0;
            for (var v = 0; v < 60; v++)
                for (var u = 0; u < 80; u++)
                {
                    var state = flow.At(camera, camera, u + 0.5, v + 0.5, out var s);
                    if (state == FlowState.NoSurface || Math.Abs(s.Pz) > 1e-9) continue; // the strip itself, or nothing
                    if (Math.Abs(s.Px + 0.5) < 1e-3) continue; // on the boundary
                    if (state == FlowState.OutsideImage) continue;
                    var expected = s.Px > -0.5 ? FlowState.Hidden : FlowState.Visible;
                    Assert.That(state, Is.EqualTo(expected), "pixel " + u + "," + v + " at x = " + s.Px);
                    if (expected == FlowState.Hidden) hidden++; else visible++;
                }
            Assert.That(hidden, Is.GreaterThan(100));
            Assert.That(visible, Is.GreaterThan(100));
        }

        /// <summary>
        /// A closed sphere turned by 70° about a tilted axis and moved, seen by one static camera: a point is visible at t′
        /// exactly when its (rotated) triangle faces the camera — an independent test of the occlusion cast. Flow is the
        /// rigid motion of the hit point projected.
        /// </summary>
        [Test]
        public void RigidSphereHidesExactlyItsBackFacingPoints()
        {
            var vertices = new List<double>();
            var triangles = new List<int>();
            FlowTestScenes.Sphere(24, 48, vertices, triangles);
            var axis = new Vector3d(0.2, 1, 0.4);
            var move = new Vector3d(0.1, 0, -0.05);
            var moved = FlowTestScenes.Rigid(vertices, axis, 70, move);
            var flow = new SurfaceFlow(vertices.ToArray(), moved, triangles.ToArray());
            var camera = FlowTestScenes.Camera(new Vector3d(0, -4, 1), new Vector3d(0, 0, 0), out var m);
            int hidden = 0, visible = 0;
            for (var v = 0; v < camera.Height; v++)
                for (var u = 0; u < camera.Width; u++)
                {
                    double x = u + 0.5, y = v + 0.5;
                    var state = flow.At(camera, camera, x, y, out var s);
                    if (state == FlowState.NoSurface) continue;
                    var q = FlowTestScenes.Rotate(new Vector3d(s.Px, s.Py, s.Pz), axis, 70) + move;
                    Assert.That(FlowTestScenes.Project(m, 60, 32, 24, q, out var x2, out var y2), Is.True);
                    Assert.That(s.Dx, Is.EqualTo(x2 - x).Within(1e-6));
                    Assert.That(s.Dy, Is.EqualTo(y2 - y).Within(1e-6));
                    int a = 3 * triangles[3 * s.Triangle], b = 3 * triangles[3 * s.Triangle + 1], c = 3 * triangles[3 * s.Triangle + 2];
                    var n = Vector3d.Cross(new Vector3d(moved[b] - moved[a], moved[b + 1] - moved[a + 1], moved[b + 2] - moved[a + 2]),
                        new Vector3d(moved[c] - moved[a], moved[c + 1] - moved[a + 1], moved[c + 2] - moved[a + 2])).Normalized();
                    var toCamera = (m.Translation - q).Normalized();
                    var facing = Vector3d.Dot(n, toCamera);
                    if (Math.Abs(facing) < 0.05) continue; // grazing: a neighbouring facet may cover it
                    Assert.That(state, Is.EqualTo(facing > 0 ? FlowState.Visible : FlowState.Hidden), "pixel " + u + "," + v);
                    if (facing > 0) visible++; else hidden++;
                }
            Assert.That(hidden, Is.GreaterThan(50));
            Assert.That(visible, Is.GreaterThan(50));
        }

        [Test]
        public void MeshesWithDifferentVertexCountsAreRefused()
        {
            var e = Assert.Throws<ArgumentException>(() => new SurfaceFlow(new double[9], new double[12], new[] { 0, 1, 2 }));
            Assert.That(e.Message, Does.Contain("3 and 4 given"));
            Assert.That(e.Message, Does.Contain("changing topology"));
        }
    }
}
