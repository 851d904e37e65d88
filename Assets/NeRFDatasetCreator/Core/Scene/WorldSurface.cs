using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A renderer's mesh, given in its local space with the renderer's local-to-world matrix, as a
    /// <see cref="SurfaceMesh"/> in world space. Points go through the matrix; normals through its normal matrix
    /// (the inverse transpose of the 3×3 part), because under a non-uniform scale the matrix itself tilts normals off
    /// their surface: a face of a cube stretched along x keeps its normal ±x, but a diagonal face's normal turns the
    /// other way than the face does. The result is renormalised; a mirroring matrix (det &lt; 0) keeps normals outward.
    /// </summary>
    public static class WorldSurface
    {
        public static SurfaceMesh FromLocal(IReadOnlyList<Vector3d> localVertices, IReadOnlyList<int> triangles, Matrix4x4d localToWorld,
            IReadOnlyList<Vector3d> localNormals = null, IReadOnlyList<Vector3d> vertexColors = null,
            IReadOnlyList<Vector3d> triangleColors = null, string name = "mesh")
        {
            if (localVertices == null) throw new ArgumentNullException(nameof(localVertices));
            var vertices = new Vector3d[localVertices.Count];
            for (var i = 0; i < vertices.Length; i++) vertices[i] = localToWorld.MultiplyPoint(localVertices[i]);
            Vector3d[] normals = null;
            if (localNormals != null)
            {
                normals = new Vector3d[localNormals.Count];
                for (var i = 0; i < normals.Length; i++) normals[i] = TransformNormal(localToWorld, localNormals[i]);
            }
            return new SurfaceMesh(vertices, triangles, normals, vertexColors, triangleColors, name);
        }

        /// <summary>
        /// A local normal in world space, unit length (zero when the normal or the matrix is degenerate):
        /// M⁻ᵀ·n = (n.x·(b × c) + n.y·(c × a) + n.z·(a × b)) / det M, with a, b, c the columns of M's 3×3 part.
        /// </summary>
        public static Vector3d TransformNormal(Matrix4x4d localToWorld, Vector3d normal)
        {
            var a = localToWorld.Column(0);
            var b = localToWorld.Column(1);
            var c = localToWorld.Column(2);
            var det = localToWorld.Determinant3x3;
            if (det == 0 || double.IsNaN(det)) return Vector3d.Zero;
            var n = (normal.X * Vector3d.Cross(b, c) + normal.Y * Vector3d.Cross(c, a) + normal.Z * Vector3d.Cross(a, b)) * Math.Sign(det);
            var length = n.Length;
            return length > 1e-300 && !double.IsInfinity(length) ? n / length : Vector3d.Zero;
        }
    }
}
