using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads a reconstruction or a ground-truth surface: PLY (through <see cref="PlyMesh"/>: ascii, binary little- or
    /// big-endian; a <c>vertex</c> element with x y z of any scalar type, optional nx ny nz, an optional <c>face</c>
    /// element whose first list property holds the indices — polygons are fanned into triangles; other elements and
    /// properties are skipped) and Wavefront OBJ (<c>v</c> and <c>f</c> lines, <c>v/vt/vn</c> and negative indices). A file with faces is a mesh, one
    /// without a point cloud. Errors name the file and what is wrong.
    /// </summary>
    public static class GeometryFile
    {
        /// <param name="option">The option that named the file, which every problem names: <c>--geometry</c> (the reconstruction) or <c>--gt-mesh</c> (the ground truth).</param>
        public static SurfaceMesh Read(string path, string option = Reconstruction)
        {
            try
            {
                if (!File.Exists(path)) throw Bad(path, "does not exist.", "Pass an existing .ply or .obj file.");
                var ext = Path.GetExtension(path).ToLowerInvariant();
                if (ext == ".ply") return ReadPly(path);
                if (ext == ".obj") return ReadObj(path);
                throw Bad(path, "is neither .ply nor .obj.", "Export the reconstruction as PLY (points or mesh) or OBJ.");
            }
            catch (InvalidParameterException e) when (option != Reconstruction)
            {
                throw new InvalidParameterException(e.Problems.Select(p => new ValidationProblem(option, p.Value, p.Reason, p.Fix)).ToList());
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem(option, path, "cannot be read: " + e.Message, "Pass an existing .ply or .obj file.") });
            }
        }

        /// <summary>The largest coordinate read: far inside float's 3.4e38, so sampled points, differences and extents stay finite.</summary>
        public const double MaxCoordinate = 1e30;

        public const string Reconstruction = "--geometry";
        public const string Truth = "--gt-mesh";

        // ---- PLY ----

        /// <summary>A PLY mesh or point cloud (<see cref="PlyMesh"/>), refused with <c>--geometry</c> problems.</summary>
        public static SurfaceMesh ReadPly(string path)
        {
            var ply = PlyMesh.Read(path, (reason, fix) => Bad(path, reason, fix));
            return Make(ply.Vertices, ply.Triangles, ply.Normals, Path.GetFileName(path), path);
        }

        // ---- OBJ ----

        public static SurfaceMesh ReadObj(string path)
        {
            var vertices = new List<Vector3d>();
            var triangles = new List<int>();
            var face = new List<int>();
            var lineNumber = 0;
            foreach (var raw in Lines(path))
            {
                lineNumber++;
                var line = raw.Trim();
                if (line.StartsWith("v ", StringComparison.Ordinal) || line.StartsWith("v\t", StringComparison.Ordinal))
                {
                    var p = line.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries);
                    if (p.Length < 4 || !TryNumber(p[1], out var x) || !TryNumber(p[2], out var y) || !TryNumber(p[3], out var z))
                        throw Bad(path + ":" + lineNumber, "is not a vertex 'v x y z'.", "Fix the OBJ file.");
                    vertices.Add(new Vector3d(x, y, z));
                }
                else if (line.StartsWith("f ", StringComparison.Ordinal) || line.StartsWith("f\t", StringComparison.Ordinal))
                {
                    face.Clear();
                    foreach (var token in line.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries).Skip(1))
                    {
                        var slash = token.IndexOf('/');
                        if (!int.TryParse(slash < 0 ? token : token.Substring(0, slash), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out var index) || index == 0)
                            throw Bad(path + ":" + lineNumber, "has an unreadable face index '" + token + "'.", "Fix the OBJ file.");
                        index = index > 0 ? index - 1 : vertices.Count + index;
                        if (index < 0 || index >= vertices.Count) throw Bad(path + ":" + lineNumber, "names vertex " + token + ", which is not defined before it.", "Fix the OBJ file.");
                        face.Add(index);
                    }
                    for (var k = 1; k + 1 < face.Count; k++)
                    {
                        triangles.Add(face[0]);
                        triangles.Add(face[k]);
                        triangles.Add(face[k + 1]);
                    }
                }
            }
            if (vertices.Count == 0) throw Bad(path, "has no vertices.", "Export the reconstruction's mesh or points.");
            return Make(vertices, triangles.Count > 0 ? triangles : null, null, Path.GetFileName(path), path);
        }

        /// <summary>The longest OBJ line read: a few numbers or indices; a longer one (a binary or hostile file) is refused, not held.</summary>
        const int MaxObjLine = 1 << 16;

        /// <summary>The file's lines, through <see cref="ReadableFile"/> (regular files only, no further than their size), each at most <see cref="MaxObjLine"/> characters.</summary>
        static IEnumerable<string> Lines(string path)
        {
            using (var reader = new StreamReader(ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes)))
            {
                var line = new System.Text.StringBuilder();
                var number = 0;
                while (true)
                {
                    var c = reader.Read();
                    if (c < 0 || c == '\n')
                    {
                        if (c < 0 && line.Length == 0) yield break;
                        number++;
                        yield return line.ToString().TrimEnd('\r');
                        line.Clear();
                        if (c < 0) yield break;
                        continue;
                    }
                    if (line.Length >= MaxObjLine) throw Bad(path + ":" + (number + 1), "has a line longer than " + MaxObjLine + " characters: it is not an OBJ text file.", "Export the reconstruction as OBJ or PLY.");
                    line.Append((char)c);
                }
            }
        }

        static bool TryNumber(string text, out double value) => double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value);

        static SurfaceMesh Make(List<Vector3d> vertices, List<int> triangles, List<Vector3d> normals, string name, string path)
        {
            for (var i = 0; i < vertices.Count; i++)
            {
                var v = vertices[i];
                if (!v.IsFinite) throw Bad(path, "has a vertex that is not finite (number " + i + ").", "Clean the reconstruction.");
                // Distances are searched in single precision (PointKdTree): 1e300 would become infinity there.
                if (Math.Abs(v.X) > MaxCoordinate || Math.Abs(v.Y) > MaxCoordinate || Math.Abs(v.Z) > MaxCoordinate)
                    throw Bad(path, "has a vertex beyond ±1e30 (number " + i + ": " + v.X.ToString("R", CultureInfo.InvariantCulture) + ", " + v.Y.ToString("R", CultureInfo.InvariantCulture) + ", " +
                                    v.Z.ToString("R", CultureInfo.InvariantCulture) + "), far outside any scene and beyond what the single-precision distance search holds.", "Clean the reconstruction, or check its units.");
            }
            return new SurfaceMesh(vertices, (IReadOnlyList<int>)triangles ?? new int[0], normals, name: name);
        }

        static InvalidParameterException Bad(string path, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("--geometry", path, reason, fix) });
    }
}
