using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The arrays the Unity side extracts from one renderer's mesh, already in world space: vertex positions,
    /// triangle indices (three per triangle), and optionally per-vertex normals, per-vertex colours or
    /// per-triangle colours (sRGB components in [0, 1], e.g. the material's base colour × vertex colour).
    /// </summary>
    public sealed class SurfaceMesh
    {
        public SurfaceMesh(IReadOnlyList<Vector3d> vertices, IReadOnlyList<int> triangles,
            IReadOnlyList<Vector3d> vertexNormals = null, IReadOnlyList<Vector3d> vertexColors = null,
            IReadOnlyList<Vector3d> triangleColors = null, string name = "mesh")
        {
            Vertices = vertices ?? throw new ArgumentNullException(nameof(vertices));
            Triangles = triangles ?? throw new ArgumentNullException(nameof(triangles));
            VertexNormals = vertexNormals;
            VertexColors = vertexColors;
            TriangleColors = triangleColors;
            Name = name ?? "mesh";
            Validate();
        }

        public IReadOnlyList<Vector3d> Vertices { get; }
        public IReadOnlyList<int> Triangles { get; }
        public IReadOnlyList<Vector3d> VertexNormals { get; }
        public IReadOnlyList<Vector3d> VertexColors { get; }
        public IReadOnlyList<Vector3d> TriangleColors { get; }
        public string Name { get; }

        public int TriangleCount => Triangles.Count / 3;

        /// <summary>Area of triangle <paramref name="t"/>: half the length of the edge cross product.</summary>
        public double TriangleArea(int t)
        {
            var a = Vertices[Triangles[3 * t]];
            var b = Vertices[Triangles[3 * t + 1]];
            var c = Vertices[Triangles[3 * t + 2]];
            return 0.5 * Vector3d.Cross(b - a, c - a).Length;
        }

        void Validate()
        {
            var problems = new List<ValidationProblem>();
            if (Triangles.Count % 3 != 0)
                problems.Add(new ValidationProblem(Name + ".triangles", Triangles.Count.ToString(System.Globalization.CultureInfo.InvariantCulture), "is not a multiple of 3.", "Pass three indices per triangle."));
            for (var i = 0; i < Triangles.Count; i++)
                if (Triangles[i] < 0 || Triangles[i] >= Vertices.Count)
                {
                    problems.Add(new ValidationProblem(Name + ".triangles[" + i + "]", Triangles[i].ToString(System.Globalization.CultureInfo.InvariantCulture), $"is not a vertex index (the mesh has {Vertices.Count} vertices).", "Pass the mesh's own index buffer."));
                    break;
                }
            for (var i = 0; i < Vertices.Count; i++)
                if (!Vertices[i].IsFinite)
                {
                    problems.Add(new ValidationProblem(Name + ".vertices[" + i + "]", Vertices[i].ToString(), "is not finite.", "Fix the mesh."));
                    break;
                }
            if (VertexNormals != null && VertexNormals.Count != Vertices.Count)
                problems.Add(new ValidationProblem(Name + ".vertexNormals", VertexNormals.Count.ToString(System.Globalization.CultureInfo.InvariantCulture), $"must have one normal per vertex ({Vertices.Count}).", "Pass mesh.normals or null."));
            if (VertexColors != null && VertexColors.Count != Vertices.Count)
                problems.Add(new ValidationProblem(Name + ".vertexColors", VertexColors.Count.ToString(System.Globalization.CultureInfo.InvariantCulture), $"must have one colour per vertex ({Vertices.Count}).", "Pass mesh.colors or null."));
            if (TriangleColors != null && TriangleColors.Count != Triangles.Count / 3)
                problems.Add(new ValidationProblem(Name + ".triangleColors", TriangleColors.Count.ToString(System.Globalization.CultureInfo.InvariantCulture), $"must have one colour per triangle ({Triangles.Count / 3}).", "Pass one colour per triangle or null."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());
        }
    }
}
