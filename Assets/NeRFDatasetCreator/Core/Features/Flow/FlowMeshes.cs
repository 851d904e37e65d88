using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The geometry pack's per-step meshes as flow needs them: vertices as doubles, one triangle list shared by every step
    /// (one topology: the same vertex count and the same triangles at every step, else flow has no point identity and the
    /// step is refused, naming it), and each step's BVH, built once and shared by every pair and video.
    /// </summary>
    public sealed class FlowMeshes
    {
        readonly Dictionary<int, double[]> _vertices = new Dictionary<int, double[]>();
        readonly Dictionary<int, TriangleBvh> _trees = new Dictionary<int, TriangleBvh>();

        public int[] Triangles { get; private set; }

        public double[] Vertices(int step) => _vertices[step];
        public TriangleBvh Tree(int step) => _trees[step];

        /// <summary>Reads every step the videos use from <paramref name="root"/>.</summary>
        public static FlowMeshes Read(string root, IReadOnlyList<FlowVideo> videos)
        {
            var meshes = new FlowMeshes();
            string firstFile = null;
            foreach (var video in videos)
                foreach (var frame in video.Frames)
                {
                    if (meshes._vertices.ContainsKey(frame.Step)) continue;
                    var path = Path.Combine(root, frame.MeshFile.Replace('/', Path.DirectorySeparatorChar));
                    var ply = PlyMesh.Read(path, (reason, fix) => Refuse(frame.MeshFile, reason, fix));
                    var vertices = new double[3 * ply.Vertices.Count];
                    for (var i = 0; i < ply.Vertices.Count; i++)
                    {
                        vertices[3 * i] = ply.Vertices[i].X;
                        vertices[3 * i + 1] = ply.Vertices[i].Y;
                        vertices[3 * i + 2] = ply.Vertices[i].Z;
                    }
                    var triangles = ply.Triangles.ToArray();
                    if (meshes.Triangles == null)
                    {
                        meshes.Triangles = triangles;
                        firstFile = frame.MeshFile;
                    }
                    else if (!SameTopology(meshes, triangles, vertices))
                        throw Refuse(frame.MeshFile, ChangedObject(root, firstFile, frame.MeshFile, meshes.Triangles, triangles) + "the target's mesh changes between steps, so a surface point at one step has no identity at the other.",
                            "Flow needs deforming meshes of one topology (skinned or animated transforms): leave objects whose mesh is rebuilt per frame out of the target. Particles are not in the geometry pack and get no flow.");
                    meshes._vertices[frame.Step] = vertices;
                    meshes._trees[frame.Step] = TriangleBvh.Build(vertices, triangles);
                }
            return meshes;
        }

        /// <summary>
        /// Which object's mesh differs, read from the two PLYs' <c>comment object</c> lines (<see cref="TargetMeshObjects"/>):
        /// "object "Cloth" has 120 triangles here and 96 in …: ". The first object that is missing, extra or of another
        /// face count, else the one holding the first differing triangle; the counts alone when the PLYs name none.
        /// </summary>
        static string ChangedObject(string root, string firstFile, string file, int[] firstTriangles, int[] triangles)
        {
            var before = TargetMeshObjects.Read(Path.Combine(root, firstFile.Replace('/', Path.DirectorySeparatorChar)));
            var after = TargetMeshObjects.Read(Path.Combine(root, file.Replace('/', Path.DirectorySeparatorChar)));
            var counts = "(" + triangles.Length / 3 + " triangles here, " + firstTriangles.Length / 3 + " in " + firstFile + "): ";
            if (before.Count == 0 || after.Count == 0) return "does not have the topology of " + firstFile + " " + counts;
            for (var i = 0; i < Math.Max(before.Count, after.Count); i++)
            {
                if (i >= after.Count) return "has no object \"" + before[i].Name + "\", which " + firstFile + " has: ";
                if (i >= before.Count) return "has object \"" + after[i].Name + "\", which " + firstFile + " does not: ";
                if (before[i].Name != after[i].Name) return "has object \"" + after[i].Name + "\" where " + firstFile + " has \"" + before[i].Name + "\": ";
                if (before[i].Faces != after[i].Faces)
                    return "has object \"" + after[i].Name + "\" with " + after[i].Faces + " triangles, " + before[i].Faces + " in " + firstFile + ": ";
            }
            for (var k = 0; k < Math.Min(firstTriangles.Length, triangles.Length); k++)
                if (firstTriangles[k] != triangles[k])
                {
                    var holder = TargetMeshObjects.Holding(after, k / 3);
                    if (holder != null) return "has object \"" + holder.Name + "\" with other triangles than in " + firstFile + " (triangle " + (k / 3 - holder.First) + " of it differs): ";
                }
            return "does not have the vertex count of " + firstFile + " " + counts;
        }

        static bool SameTopology(FlowMeshes meshes, int[] triangles, double[] vertices)
        {
            var first = meshes.Triangles;
            if (first.Length != triangles.Length) return false;
            foreach (var v in meshes._vertices.Values) { if (v.Length != vertices.Length) return false; break; }
            for (var i = 0; i < first.Length; i++) if (first[i] != triangles[i]) return false;
            return true;
        }

        static InvalidParameterException Refuse(string file, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("geometry", file, reason, fix) });
    }
}
