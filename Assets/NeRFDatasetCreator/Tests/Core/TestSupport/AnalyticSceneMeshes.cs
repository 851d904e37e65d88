using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <see cref="AnalyticScene.Layout"/> as triangle meshes in Unity's world (what the Editor's TargetSurface reads), from
    /// the same layout numbers: the
    /// opaque sphere (moving 0.4 along Unity +X over normalised time), the glass sphere and the slab, around
    /// <see cref="AnalyticDataset.Centre"/>. Spheres are UV spheres fine enough that their facets stay within a few
    /// thousandths of the analytic surface the depth maps hold.
    /// </summary>
    static class AnalyticSceneMeshes
    {
        public static IReadOnlyList<SurfaceMesh> At(double time)
        {
            var c = AnalyticDataset.Centre;
            return new[]
            {
                Moved(AnalyticSphereDataset.UvSphere(AnalyticScene.OpaqueRadius, 64, 128, "opaque"), c + AnalyticScene.OpaqueOffset(time)),
                Moved(AnalyticSphereDataset.UvSphere(AnalyticScene.GlassRadius, 48, 96, "glass"), c + AnalyticScene.GlassOffset),
                Box(c + AnalyticScene.SlabLow, c + AnalyticScene.SlabHigh),
            };
        }

        static SurfaceMesh Moved(SurfaceMesh mesh, Vector3d by) =>
            new SurfaceMesh(mesh.Vertices.Select(v => v + by).ToList(), mesh.Triangles, mesh.VertexNormals, name: mesh.Name);

        /// <summary>An axis-aligned box, two triangles per face (flat-shaded: four vertices per face).</summary>
        static SurfaceMesh Box(Vector3d min, Vector3d max)
        {
            var vertices = new List<Vector3d>();
            var triangles = new List<int>();
            for (var axis = 0; axis < 3; axis++)
                foreach (var high in new[] { false, true })
                {
                    var u = (axis + 1) % 3;
                    var v = (axis + 2) % 3;
                    var first = vertices.Count;
                    foreach (var (a, b) in new[] { (0, 0), (1, 0), (1, 1), (0, 1) })
                    {
                        var p = new double[3];
                        p[axis] = high ? Get(max, axis) : Get(min, axis);
                        p[u] = a == 0 ? Get(min, u) : Get(max, u);
                        p[v] = b == 0 ? Get(min, v) : Get(max, v);
                        vertices.Add(new Vector3d(p[0], p[1], p[2]));
                    }
                    triangles.AddRange(new[] { first, first + 1, first + 2, first, first + 2, first + 3 });
                }
            return new SurfaceMesh(vertices, triangles, null, name: "slab");
        }

        static double Get(Vector3d p, int axis) => axis == 0 ? p.X : axis == 1 ? p.Y : p.Z;
    }
}
