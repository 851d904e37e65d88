using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <see cref="AnalyticScene.Layout"/> as triangle meshes in Unity's world (what the Editor's TargetSurface reads), from
    /// the same layout numbers: the
    /// opaque sphere (moving 0.4 along Unity +X over normalised time), the glass sphere and the slab, around
    /// <see cref="AnalyticDataset.Centre"/>. Spheres are UV spheres fine enough that their facets stay within a few
    /// thousandths of the analytic surface the depth maps hold.
    /// </summary>
    public static class AnalyticSceneMeshes
    {
        /// <summary>The tests' layout at normalised <paramref name="time"/>.</summary>
        public static IReadOnlyList<SurfaceMesh> At(double time) => At(time, AnalyticLook.Test);

        /// <summary>The layout of <paramref name="look"/> at normalised <paramref name="time"/> (the demo's has the crate too).</summary>
        public static IReadOnlyList<SurfaceMesh> At(double time, AnalyticLook look)
        {
            var c = AnalyticDataset.Centre;
            var meshes = new List<SurfaceMesh>
            {
                Moved(UvSphere(AnalyticScene.OpaqueRadius, 64, 128, "opaque"), c + AnalyticScene.OpaqueOffset(time)),
                Moved(UvSphere(AnalyticScene.GlassRadius, 48, 96, "glass"), c + AnalyticScene.GlassOffset),
                Box(c + AnalyticScene.SlabLow, c + AnalyticScene.SlabHigh, "slab"),
            };
            if (look == AnalyticLook.Demo) meshes.Add(Box(c + AnalyticScene.CrateLow, c + AnalyticScene.CrateHigh, "crate"));
            return meshes;
        }

        /// <summary>A UV sphere centred at the origin, faces counter-clockwise seen from outside, unit normals.</summary>
        public static SurfaceMesh UvSphere(double radius, int rings, int segments, string name = "sphere")
        {
            var vertices = new List<Vector3d>();
            var normals = new List<Vector3d>();
            for (var r = 0; r <= rings; r++)
            {
                var theta = Math.PI * r / rings;
                for (var s = 0; s < segments; s++)
                {
                    var phi = 2 * Math.PI * s / segments;
                    var n = new Vector3d(Math.Sin(theta) * Math.Cos(phi), Math.Sin(theta) * Math.Sin(phi), Math.Cos(theta));
                    vertices.Add(n * radius);
                    normals.Add(n);
                }
            }
            var triangles = new List<int>();
            for (var r = 0; r < rings; r++)
                for (var s = 0; s < segments; s++)
                {
                    int a = r * segments + s, b = r * segments + (s + 1) % segments, c = (r + 1) * segments + s, d = (r + 1) * segments + (s + 1) % segments;
                    // (c − a) runs along e_θ, (b − a) along e_φ and e_θ × e_φ = e_r: (a, c, b) and (b, c, d) are counter-clockwise seen from outside.
                    if (r > 0) { triangles.Add(a); triangles.Add(c); triangles.Add(b); }
                    if (r < rings - 1) { triangles.Add(b); triangles.Add(c); triangles.Add(d); }
                }
            return new SurfaceMesh(vertices, triangles, normals, name: name);
        }

        static SurfaceMesh Moved(SurfaceMesh mesh, Vector3d by) =>
            new SurfaceMesh(mesh.Vertices.Select(v => v + by).ToList(), mesh.Triangles, mesh.VertexNormals, name: mesh.Name);

        /// <summary>An axis-aligned box, two triangles per face (flat-shaded: four vertices per face).</summary>
        static SurfaceMesh Box(Vector3d min, Vector3d max, string name)
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
            return new SurfaceMesh(vertices, triangles, null, name: name);
        }

        static double Get(Vector3d p, int axis) => axis == 0 ? p.X : axis == 1 ? p.Y : p.Z;
    }
}
