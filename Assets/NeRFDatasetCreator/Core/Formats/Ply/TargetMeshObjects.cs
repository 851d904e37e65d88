using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>One source object of a geometry-pack PLY: its name and its faces [First, First + Faces).</summary>
    public sealed class TargetMeshObject
    {
        public TargetMeshObject(string name, long first, long faces)
        {
            Name = name;
            First = first;
            Faces = faces;
        }

        public string Name { get; }
        public long First { get; }
        public long Faces { get; }
    }

    /// <summary>
    /// The <c>comment object &lt;name&gt; &lt;first face&gt; &lt;faces&gt;</c> lines of a geometry-pack PLY's header
    /// (<see cref="TargetMeshPly.Write"/>): which faces came from which object, so a refusal can name the object.
    /// </summary>
    public static class TargetMeshObjects
    {
        const string Prefix = "comment object ";

        /// <summary>The objects in face order; empty when the header has none or cannot be read (a PLY of another writer).</summary>
        public static IReadOnlyList<TargetMeshObject> Read(string path)
        {
            var result = new List<TargetMeshObject>();
            try
            {
                using (var stream = File.OpenRead(path))
                {
                    var line = new StringBuilder();
                    // The header is ASCII lines up to end_header; 1 MB is far beyond any header this plugin writes.
                    for (var read = 0; read < 1 << 20; read++)
                    {
                        var b = stream.ReadByte();
                        if (b < 0) break;
                        if (b != '\n') { line.Append((char)b); continue; }
                        var text = line.ToString().TrimEnd('\r');
                        line.Clear();
                        if (text == "end_header") break;
                        if (!text.StartsWith(Prefix, StringComparison.Ordinal)) continue;
                        var parts = text.Substring(Prefix.Length).Split(' ');
                        if (parts.Length == 3 && long.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out var first)
                            && long.TryParse(parts[2], NumberStyles.None, CultureInfo.InvariantCulture, out var faces))
                            result.Add(new TargetMeshObject(parts[0], first, faces));
                    }
                }
            }
            catch (IOException) { return new List<TargetMeshObject>(); }
            catch (UnauthorizedAccessException) { return new List<TargetMeshObject>(); }
            return result;
        }

        /// <summary>The object that holds face <paramref name="face"/>, or null.</summary>
        public static TargetMeshObject Holding(IReadOnlyList<TargetMeshObject> objects, long face)
        {
            foreach (var o in objects)
                if (face >= o.First && face < o.First + o.Faces) return o;
            return null;
        }
    }
}
