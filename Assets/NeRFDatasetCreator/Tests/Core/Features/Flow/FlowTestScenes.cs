using System;
using System.Collections.Generic;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Meshes and cameras for the flow tests, built by hand (output frame, OpenGL camera axes).</summary>
    static class FlowTestScenes
    {
        /// <summary>
        /// A camera at <paramref name="eye"/> looking at <paramref name="target"/> with world +Z up on the image:
        /// −Z_cam = forward, +X_cam = forward × up, +Y_cam = X_cam × forward; 64×48 px, fx = fy = 60, principal point at the centre.
        /// </summary>
        public static FlowCamera Camera(Vector3d eye, Vector3d target, int width = 64, int height = 48, double focal = 60) => Camera(eye, target, out _, width, height, focal);

        public static FlowCamera Camera(Vector3d eye, Vector3d target, out Matrix4x4d cameraToWorld, int width = 64, int height = 48, double focal = 60)
        {
            var forward = (target - eye).Normalized();
            var up = Math.Abs(forward.Z) > 0.999 ? Vector3d.UnitY : Vector3d.UnitZ;
            var right = Vector3d.Cross(forward, up).Normalized();
            var cameraUp = Vector3d.Cross(right, forward);
            cameraToWorld = Matrix4x4d.FromColumns(right, cameraUp, -forward, eye);
            return new FlowCamera(cameraToWorld, focal, focal, width / 2.0, height / 2.0, width, height);
        }

        /// <summary>An n×n grid of quads (2 triangles each) over [−1, 1]² in the plane z = <paramref name="z"/>.</summary>
        public static void Grid(int n, double z, List<double> vertices, List<int> triangles, double x0 = -1, double x1 = 1)
        {
            var first = vertices.Count / 3;
            for (var j = 0; j <= n; j++)
                for (var i = 0; i <= n; i++)
                {
                    vertices.Add(x0 + (x1 - x0) * i / n);
                    vertices.Add(-1 + 2.0 * j / n);
                    vertices.Add(z);
                }
            for (var j = 0; j < n; j++)
                for (var i = 0; i < n; i++)
                {
                    int a = first + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                    triangles.AddRange(new[] { a, b, d, a, d, c });
                }
        }

        /// <summary>A UV sphere of radius 1 at the origin (outward-wound), <paramref name="rings"/> × <paramref name="segments"/>.</summary>
        public static void Sphere(int rings, int segments, List<double> vertices, List<int> triangles)
        {
            for (var r = 0; r <= rings; r++)
            {
                var theta = Math.PI * r / rings;
                for (var s = 0; s < segments; s++)
                {
                    var phi = 2 * Math.PI * s / segments;
                    vertices.Add(Math.Sin(theta) * Math.Cos(phi));
                    vertices.Add(Math.Sin(theta) * Math.Sin(phi));
                    vertices.Add(Math.Cos(theta));
                }
            }
            for (var r = 0; r < rings; r++)
                for (var s = 0; s < segments; s++)
                {
                    int a = r * segments + s, b = r * segments + (s + 1) % segments, c = a + segments, d = b + segments;
                    if (r > 0) triangles.AddRange(new[] { a, c, b });
                    if (r < rings - 1) triangles.AddRange(new[] { b, c, d });
                }
        }

        /// <summary>Each vertex moved by x ↦ R·x + t, R a rotation by <paramref name="degrees"/> about <paramref name="axis"/>.</summary>
        public static double[] Rigid(IReadOnlyList<double> vertices, Vector3d axis, double degrees, Vector3d t)
        {
            var moved = new double[vertices.Count];
            for (var i = 0; i < vertices.Count; i += 3)
            {
                var p = Rotate(new Vector3d(vertices[i], vertices[i + 1], vertices[i + 2]), axis, degrees) + t;
                moved[i] = p.X;
                moved[i + 1] = p.Y;
                moved[i + 2] = p.Z;
            }
            return moved;
        }

        /// <summary>Rodrigues' rotation of <paramref name="p"/> about the unit <paramref name="axis"/>.</summary>
        public static Vector3d Rotate(Vector3d p, Vector3d axis, double degrees)
        {
            var k = axis.Normalized();
            double a = degrees * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
            return p * c + Vector3d.Cross(k, p) * s + k * (Vector3d.Dot(k, p) * (1 - c));
        }

        /// <summary>Continuous pixel coordinates of a world point, by the camera's matrices (independent of FlowCamera.Project).</summary>
        public static bool Project(Matrix4x4d cameraToWorld, double f, double cx, double cy, Vector3d p, out double x, out double y)
        {
            var c = cameraToWorld.InverseRigid().MultiplyPoint(p);
            x = y = double.NaN;
            if (c.Z >= 0) return false;
            x = cx + f * c.X / -c.Z;
            y = cy - f * c.Y / -c.Z;
            return true;
        }
    }
}
