using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads a reconstruction or a ground-truth surface: PLY (ascii, binary little- or big-endian; a <c>vertex</c>
    /// element with x y z of any scalar type, optional nx ny nz, an optional <c>face</c> element whose first list
    /// property holds the indices — polygons are fanned into triangles; other elements and properties are skipped) and
    /// Wavefront OBJ (<c>v</c> and <c>f</c> lines, <c>v/vt/vn</c> and negative indices). A file with faces is a mesh, one
    /// without a point cloud. Errors name the file and what is wrong.
    /// </summary>
    public static class GeometryFile
    {
        public static SurfaceMesh Read(string path)
        {
            if (!File.Exists(path)) throw Bad(path, "does not exist.", "Pass an existing .ply or .obj file.");
            var ext = Path.GetExtension(path).ToLowerInvariant();
            if (ext == ".ply") return ReadPly(path);
            if (ext == ".obj") return ReadObj(path);
            throw Bad(path, "is neither .ply nor .obj.", "Export the reconstruction as PLY (points or mesh) or OBJ.");
        }

        // ---- PLY ----

        sealed class Property
        {
            public string Name, Type, CountType;
            public bool IsList => CountType != null;
        }

        sealed class Element
        {
            public string Name;
            public long Count;
            public readonly List<Property> Properties = new List<Property>();
        }

        public static SurfaceMesh ReadPly(string path)
        {
            using (var stream = new BufferedStream(File.OpenRead(path), 1 << 16))
            {
                var lines = new List<string>();
                var line = new StringBuilder();
                while (true)
                {
                    var b = stream.ReadByte();
                    if (b < 0) throw Bad(path, "ends inside its PLY header.", "Re-export the file.");
                    if (b == '\n')
                    {
                        var text = line.ToString().TrimEnd('\r');
                        line.Clear();
                        lines.Add(text);
                        if (text == "end_header") break;
                        if (lines.Count > 10000) throw Bad(path, "has no end_header.", "Re-export the file.");
                    }
                    else line.Append((char)b);
                }
                if (lines.Count == 0 || lines[0] != "ply") throw Bad(path, "is not a PLY file (no 'ply' first line).", "Export as PLY.");
                string format = null;
                var elements = new List<Element>();
                foreach (var l in lines.Skip(1))
                {
                    var parts = l.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries);
                    if (parts.Length == 0 || parts[0] == "comment" || parts[0] == "obj_info") continue;
                    if (parts[0] == "format" && parts.Length >= 2) format = parts[1];
                    else if (parts[0] == "element" && parts.Length == 3) elements.Add(new Element { Name = parts[1], Count = long.Parse(parts[2], CultureInfo.InvariantCulture) });
                    else if (parts[0] == "property" && elements.Count > 0)
                    {
                        if (parts.Length == 5 && parts[1] == "list") elements[elements.Count - 1].Properties.Add(new Property { CountType = parts[2], Type = parts[3], Name = parts[4] });
                        else if (parts.Length == 3) elements[elements.Count - 1].Properties.Add(new Property { Type = parts[1], Name = parts[2] });
                        else throw Bad(path, "has an unreadable header line '" + l + "'.", "Re-export the file.");
                    }
                }
                if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
                    throw Bad(path, "has PLY format '" + format + "'.", "Export as ascii or binary PLY.");
                var vertexElement = elements.FirstOrDefault(e => e.Name == "vertex");
                if (vertexElement == null || vertexElement.Count == 0) throw Bad(path, "has no vertices.", "Export the reconstruction's points or mesh.");
                if (vertexElement.Count > int.MaxValue / 4) throw Bad(path, "has " + vertexElement.Count + " vertices, more than this tool reads.", "Subsample the reconstruction.");
                int ix = vertexElement.Properties.FindIndex(p => p.Name == "x"), iy = vertexElement.Properties.FindIndex(p => p.Name == "y"), iz = vertexElement.Properties.FindIndex(p => p.Name == "z");
                if (ix < 0 || iy < 0 || iz < 0) throw Bad(path, "has no x, y, z vertex properties.", "Export vertex positions as x y z.");
                int inx = vertexElement.Properties.FindIndex(p => p.Name == "nx"), iny = vertexElement.Properties.FindIndex(p => p.Name == "ny"), inz = vertexElement.Properties.FindIndex(p => p.Name == "nz");
                var hasNormals = inx >= 0 && iny >= 0 && inz >= 0;

                var reader = new PlyValueReader(stream, format, path);
                var vertices = new List<Vector3d>((int)vertexElement.Count);
                var normals = hasNormals ? new List<Vector3d>((int)vertexElement.Count) : null;
                var triangles = new List<int>();
                var hasFaces = false;
                var values = new double[64];
                foreach (var element in elements)
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
                                if (count < 0 || count > 1 << 20) throw Bad(path, "has a list of " + count + " entries in element " + element.Name + ".", "Re-export the file.");
                                if (isFace && p == 0)
                                {
                                    if (count > values.Length) values = new double[count];
                                    for (var k = 0; k < count; k++) values[k] = reader.Read(property.Type);
                                    for (var k = 1; k + 1 < count; k++)
                                    {
                                        triangles.Add(Index(values[0], vertexElement.Count, path));
                                        triangles.Add(Index(values[k], vertexElement.Count, path));
                                        triangles.Add(Index(values[k + 1], vertexElement.Count, path));
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
                return Make(vertices, hasFaces ? triangles : null, normals, Path.GetFileName(path), path);
            }
        }

        static int Index(double value, long vertexCount, string path)
        {
            if (!(value >= 0 && value < vertexCount)) throw Bad(path, "has a face index " + value.ToString(CultureInfo.InvariantCulture) + " outside its " + vertexCount + " vertices.", "Re-export the mesh.");
            return (int)value;
        }

        /// <summary>Reads PLY scalars of any type from ascii or binary data.</summary>
        sealed class PlyValueReader
        {
            readonly Stream stream;
            readonly string format, path;
            readonly byte[] buffer = new byte[8];
            string[] tokens = new string[0];
            int next;

            public PlyValueReader(Stream stream, string format, string path)
            {
                this.stream = stream;
                this.format = format;
                this.path = path;
            }

            public void NextLine()
            {
                var line = new StringBuilder();
                while (true)
                {
                    var b = stream.ReadByte();
                    if (b < 0) { if (line.Length == 0) throw Bad(path, "ends before all its elements.", "Re-export the file."); break; }
                    if (b == '\n') { if (line.ToString().Trim().Length == 0) { line.Clear(); continue; } break; }
                    line.Append((char)b);
                }
                tokens = line.ToString().Split(new[] { ' ', '\t', '\r' }, StringSplitOptions.RemoveEmptyEntries);
                next = 0;
            }

            public double Read(string type)
            {
                if (format == "ascii")
                {
                    if (next >= tokens.Length) throw Bad(path, "has a short ascii line.", "Re-export the file.");
                    return double.Parse(tokens[next++], NumberStyles.Float, CultureInfo.InvariantCulture);
                }
                var size = Size(type);
                var read = 0;
                while (read < size)
                {
                    var n = stream.Read(buffer, read, size - read);
                    if (n <= 0) throw Bad(path, "ends before all its elements.", "Re-export the file.");
                    read += n;
                }
                if ((format == "binary_big_endian") == BitConverter.IsLittleEndian) Array.Reverse(buffer, 0, size);
                switch (type)
                {
                    case "char": case "int8": return (sbyte)buffer[0];
                    case "uchar": case "uint8": return buffer[0];
                    case "short": case "int16": return BitConverter.ToInt16(buffer, 0);
                    case "ushort": case "uint16": return BitConverter.ToUInt16(buffer, 0);
                    case "int": case "int32": return BitConverter.ToInt32(buffer, 0);
                    case "uint": case "uint32": return BitConverter.ToUInt32(buffer, 0);
                    case "float": case "float32": return BitConverter.ToSingle(buffer, 0);
                    default: return BitConverter.ToDouble(buffer, 0);
                }
            }

            int Size(string type)
            {
                switch (type)
                {
                    case "char": case "int8": case "uchar": case "uint8": return 1;
                    case "short": case "int16": case "ushort": case "uint16": return 2;
                    case "int": case "int32": case "uint": case "uint32": case "float": case "float32": return 4;
                    case "double": case "float64": return 8;
                    default: throw Bad(path, "has a property of unknown type '" + type + "'.", "Re-export the file.");
                }
            }
        }

        // ---- OBJ ----

        public static SurfaceMesh ReadObj(string path)
        {
            var vertices = new List<Vector3d>();
            var triangles = new List<int>();
            var face = new List<int>();
            var lineNumber = 0;
            foreach (var raw in File.ReadLines(path))
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

        static bool TryNumber(string text, out double value) => double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value);

        static SurfaceMesh Make(List<Vector3d> vertices, List<int> triangles, List<Vector3d> normals, string name, string path)
        {
            for (var i = 0; i < vertices.Count; i++)
                if (!vertices[i].IsFinite) throw Bad(path, "has a vertex that is not finite (number " + i + ").", "Clean the reconstruction.");
            return new SurfaceMesh(vertices, (IReadOnlyList<int>)triangles ?? new int[0], normals, name: name);
        }

        static InvalidParameterException Bad(string path, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("--geometry", path, reason, fix) });
    }
}
