using System;
using System.Collections.Generic;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The geometry pack's mesh, <c>geometry/target_mesh.ply</c>: the target's triangles in the output frame and units
    /// (the frame of <c>transform_matrix</c> and of the depth maps), binary little-endian PLY with float
    /// <c>x y z nx ny nz</c> per vertex and <c>uchar int vertex_indices</c> per face, faces counter-clockwise seen from
    /// outside (the right-hand rule gives the outward normal, as MeshLab, Open3D and trimesh expect). The meshes are
    /// concatenated; one <c>comment object &lt;name&gt; &lt;first face&gt; &lt;faces&gt;</c> line per source mesh says which
    /// faces came from which object. <see cref="PlyMesh"/> reads it back (<see cref="GeometryFile.ReadPly"/>).
    /// </summary>
    public static class TargetMeshPly
    {
        public const string Folder = "geometry";
        public const string FileName = "target_mesh.ply";
        public const string RelativePath = Folder + "/" + FileName;
        public const string Signature = PluginInfo.Name + ": the target's triangle mesh, output frame and units; see dataset_config.json geometry";

        /// <summary>
        /// Unity-world meshes moved into the output world: positions through <paramref name="normalisation"/>, normals
        /// relabelled (Y/Z swap). The swap is a reflection, so a triangle's index order is reversed (i0, i2, i1): Unity's
        /// clockwise front faces stay front faces under the right-hand rule of the output frame.
        /// </summary>
        public static IReadOnlyList<SurfaceMesh> FromUnityWorld(IReadOnlyList<SurfaceMesh> unityWorldMeshes, SceneNormalisation normalisation)
        {
            var result = new List<SurfaceMesh>();
            foreach (var mesh in unityWorldMeshes)
            {
                var vertices = new Vector3d[mesh.Vertices.Count];
                for (var i = 0; i < vertices.Length; i++) vertices[i] = normalisation.ApplyToUnityPoint(mesh.Vertices[i]);
                Vector3d[] normals = null;
                if (mesh.VertexNormals != null)
                {
                    normals = new Vector3d[mesh.VertexNormals.Count];
                    for (var i = 0; i < normals.Length; i++) normals[i] = BlenderConvention.FromUnity(mesh.VertexNormals[i]);
                }
                var triangles = new int[mesh.Triangles.Count];
                for (var t = 0; t + 2 < triangles.Length; t += 3)
                {
                    triangles[t] = mesh.Triangles[t];
                    triangles[t + 1] = mesh.Triangles[t + 2];
                    triangles[t + 2] = mesh.Triangles[t + 1];
                }
                result.Add(new SurfaceMesh(vertices, triangles, normals, name: mesh.Name));
            }
            return result;
        }

        /// <summary>Writes the meshes (output frame) as one PLY. Vertices without normals get the area-weighted face normal.</summary>
        public static void Write(Stream stream, IReadOnlyList<SurfaceMesh> meshes)
        {
            long vertexCount = 0, faceCount = 0;
            foreach (var m in meshes)
            {
                vertexCount += m.Vertices.Count;
                faceCount += m.TriangleCount;
            }
            if (vertexCount > int.MaxValue || faceCount > int.MaxValue) throw new ArgumentException("The target has more than 2³¹ vertices or faces.");
            var header = new StringBuilder();
            header.Append("ply\nformat binary_little_endian 1.0\ncomment ").Append(Signature).Append('\n');
            long first = 0;
            foreach (var m in meshes)
            {
                header.Append("comment object ").Append(CommentSafe(m.Name)).Append(' ').Append(first.ToString(System.Globalization.CultureInfo.InvariantCulture))
                    .Append(' ').Append(m.TriangleCount.ToString(System.Globalization.CultureInfo.InvariantCulture)).Append('\n');
                first += m.TriangleCount;
            }
            header.Append("element vertex ").Append(vertexCount.ToString(System.Globalization.CultureInfo.InvariantCulture)).Append('\n')
                .Append("property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n")
                .Append("element face ").Append(faceCount.ToString(System.Globalization.CultureInfo.InvariantCulture)).Append('\n')
                .Append("property list uchar int vertex_indices\nend_header\n");
            var bytes = Encoding.ASCII.GetBytes(header.ToString());
            stream.Write(bytes, 0, bytes.Length);
            using (var writer = new BinaryWriter(stream, Encoding.ASCII, leaveOpen: true))
            {
                foreach (var m in meshes)
                {
                    var normals = m.VertexNormals ?? FaceNormals(m);
                    for (var i = 0; i < m.Vertices.Count; i++)
                    {
                        var p = m.Vertices[i];
                        var n = normals[i];
                        writer.Write((float)p.X); writer.Write((float)p.Y); writer.Write((float)p.Z);
                        writer.Write((float)n.X); writer.Write((float)n.Y); writer.Write((float)n.Z);
                    }
                }
                var offset = 0;
                foreach (var m in meshes)
                {
                    for (var t = 0; t < m.Triangles.Count; t += 3)
                    {
                        writer.Write((byte)3);
                        writer.Write(offset + m.Triangles[t]);
                        writer.Write(offset + m.Triangles[t + 1]);
                        writer.Write(offset + m.Triangles[t + 2]);
                    }
                    offset += m.Vertices.Count;
                }
            }
        }

        public static void Write(string path, IReadOnlyList<SurfaceMesh> meshes)
        {
            using (var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write))
            using (var buffered = new BufferedStream(file, 1 << 16))
                Write(buffered, meshes);
        }

        /// <summary>Per-vertex normals from the right-hand rule of the faces around each vertex, area-weighted, unit length.</summary>
        public static Vector3d[] FaceNormals(SurfaceMesh mesh)
        {
            var sums = new Vector3d[mesh.Vertices.Count];
            for (var t = 0; t + 2 < mesh.Triangles.Count; t += 3)
            {
                int a = mesh.Triangles[t], b = mesh.Triangles[t + 1], c = mesh.Triangles[t + 2];
                var n = Vector3d.Cross(mesh.Vertices[b] - mesh.Vertices[a], mesh.Vertices[c] - mesh.Vertices[a]);
                sums[a] = sums[a] + n;
                sums[b] = sums[b] + n;
                sums[c] = sums[c] + n;
            }
            for (var i = 0; i < sums.Length; i++) sums[i] = sums[i].LengthSquared > 0 ? sums[i].Normalized() : Vector3d.Zero;
            return sums;
        }

        /// <summary>An object name fit for one header word (no spaces or line breaks).</summary>
        static string CommentSafe(string name)
        {
            var s = new StringBuilder();
            foreach (var c in string.IsNullOrEmpty(name) ? "mesh" : name) s.Append(char.IsWhiteSpace(c) || c < 32 || c > 126 ? '_' : c);
            return s.ToString();
        }
    }
}
