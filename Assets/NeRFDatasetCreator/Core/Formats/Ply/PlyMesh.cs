using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A surface from any PLY file: ascii, binary little- or big-endian; a <c>vertex</c> element with x y z of any
    /// scalar type, optional nx ny nz, an optional <c>face</c> element whose first list property holds the indices —
    /// polygons are fanned into triangles; other elements and properties are skipped. <see cref="GeometryFile"/> reads
    /// reconstructions and the geometry pack's <see cref="TargetMeshPly"/> through it.
    /// </summary>
    public sealed class PlyMesh
    {
        /// <summary>Header lines up to and including end_header: a header longer than 10000 lines has none.</summary>
        const int MaxHeaderLines = 10000 + 1;

        /// <summary>Header bytes read at most: 10000 lines of 100 characters.</summary>
        const int MaxHeaderBytes = 1 << 20;

        PlyMesh(List<Vector3d> vertices, List<int> triangles, List<Vector3d> normals)
        {
            Vertices = vertices;
            Triangles = triangles;
            Normals = normals;
        }

        public List<Vector3d> Vertices { get; }

        /// <summary>Three vertex indices per triangle; null when the file has no faces (a point cloud).</summary>
        public List<int> Triangles { get; }

        /// <summary>One per vertex; null when the vertices have no nx ny nz.</summary>
        public List<Vector3d> Normals { get; }

        /// <param name="fail">Makes the exception for a reason and its fix, e.g. ("has no vertices.", "Export the reconstruction's points or mesh.").</param>
        public static PlyMesh Read(string path, Func<string, string, Exception> fail)
        {
            using (var stream = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
            {
                var header = PlyHeader.Read(stream, MaxHeaderBytes, MaxHeaderLines);
                if (header.CutShort) throw fail("ends inside its PLY header.", "Re-export the file.");
                if (!header.Ended) throw fail("has no end_header.", "Re-export the file.");
                if (header.Lines[0] != "ply") throw fail("is not a PLY file (no 'ply' first line).", "Export as PLY.");
                var unreadable = header.Declare();
                if (unreadable != null) throw fail("has an unreadable header line '" + unreadable + "'.", "Re-export the file.");
                var format = header.Format;
                if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
                    throw fail("has PLY format '" + format + "'.", "Export as ascii or binary PLY.");
                var vertexElement = header.Elements.FirstOrDefault(e => e.Name == "vertex");
                if (vertexElement == null || vertexElement.Count == 0) throw fail("has no vertices.", "Export the reconstruction's points or mesh.");
                if (vertexElement.Count > int.MaxValue / 4) throw fail("has " + vertexElement.Count + " vertices, more than this tool reads.", "Subsample the reconstruction.");
                int ix = vertexElement.Properties.FindIndex(p => p.Name == "x"), iy = vertexElement.Properties.FindIndex(p => p.Name == "y"), iz = vertexElement.Properties.FindIndex(p => p.Name == "z");
                if (ix < 0 || iy < 0 || iz < 0) throw fail("has no x, y, z vertex properties.", "Export vertex positions as x y z.");
                int inx = vertexElement.Properties.FindIndex(p => p.Name == "nx"), iny = vertexElement.Properties.FindIndex(p => p.Name == "ny"), inz = vertexElement.Properties.FindIndex(p => p.Name == "nz");
                var hasNormals = inx >= 0 && iny >= 0 && inz >= 0;

                var reader = new PlyValueReader(stream, format, reason => fail(reason, "Re-export the file."));
                // What the header claims must fit in what follows it, checked before a list of its size is allocated.
                var available = stream.Length - stream.Position;
                var needed = header.MinimumDataBytes(reader.SizeOf);
                if (needed > available)
                    throw fail("is truncated: its header declares " + string.Join(", ", header.Elements.Select(e => "element " + e.Name + " " + e.Count)) + ", at least " +
                               needed.ToString("0", CultureInfo.InvariantCulture) + " bytes of " + format + " data, but only " + available + " bytes follow the header.", "Re-export the file.");
                var vertices = new List<Vector3d>((int)vertexElement.Count);
                var normals = hasNormals ? new List<Vector3d>((int)vertexElement.Count) : null;
                var triangles = new List<int>();
                var hasFaces = false;
                var values = new double[64];
                foreach (var element in header.Elements)
                {
                    var isVertex = element == vertexElement;
                    var isFace = element.Name == "face" && element.Properties.Count > 0 && element.Properties[0].IsList;
                    if (isFace) hasFaces = true;
                    for (long n = 0; n < element.Count; n++)
                    {
                        if (format == "ascii") reader.NextLine();
                        for (var p = 0; p < element.Properties.Count; p++)
                        {
                            var property = element.Properties[p];
                            if (property.IsList)
                            {
                                var count = (int)reader.Read(property.CountType);
                                if (count < 0 || count > 1 << 20) throw fail("has a list of " + count + " entries in element " + element.Name + ".", "Re-export the file.");
                                if (isFace && p == 0)
                                {
                                    if (count > values.Length) values = new double[count];
                                    for (var k = 0; k < count; k++) values[k] = reader.Read(property.Type);
                                    for (var k = 1; k + 1 < count; k++)
                                    {
                                        triangles.Add(Index(values[0], vertexElement.Count, fail));
                                        triangles.Add(Index(values[k], vertexElement.Count, fail));
                                        triangles.Add(Index(values[k + 1], vertexElement.Count, fail));
                                    }
                                }
                                else for (var k = 0; k < count; k++) reader.Read(property.Type);
                            }
                            else
                            {
                                var v = reader.Read(property.Type);
                                if (isVertex && p < values.Length) values[p] = v;
                            }
                        }
                        if (isVertex)
                        {
                            vertices.Add(new Vector3d(values[ix], values[iy], values[iz]));
                            if (hasNormals) normals.Add(new Vector3d(values[inx], values[iny], values[inz]));
                        }
                    }
                }
                return new PlyMesh(vertices, hasFaces ? triangles : null, normals);
            }
        }

        static int Index(double value, long vertexCount, Func<string, string, Exception> fail)
        {
            if (!(value >= 0 && value < vertexCount)) throw fail("has a face index " + value.ToString(CultureInfo.InvariantCulture) + " outside its " + vertexCount + " vertices.", "Re-export the mesh.");
            return (int)value;
        }
    }
}
