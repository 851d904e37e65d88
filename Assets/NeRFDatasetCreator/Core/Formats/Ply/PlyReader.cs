using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Reads back exactly the layout <see cref="PlyWriter"/> writes (and 3DGS's storePly): binary little-endian,
    /// one vertex element, float x y z nx ny nz, uchar red green blue, any comment lines. Anything else is refused with a message
    /// rather than misread; a general PLY reader is out of scope.
    /// </summary>
    public static class PlyReader
    {
        /// <summary>Bytes per vertex: six float32 and three uint8.</summary>
        public const int VertexBytes = 6 * 4 + 3;

        /// <summary>The points; a file that is not this layout, is truncated or cannot be read is a problem naming it.</summary>
        public static IReadOnlyList<CloudPoint> Read(string path)
        {
            try
            {
                return ReadPoints(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw Problem(path, "cannot be read: " + e.Message);
            }
        }

        static IReadOnlyList<CloudPoint> ReadPoints(string path)
        {
            using (var file = File.OpenRead(path))
            {
                var header = ReadHeader(file);
                var count = ParseCount(header, path);
                var expected = WithoutComments(PlyWriter.Header(count));
                if (WithoutComments(header) != expected)
                    throw Problem(path, "is not a binary little-endian PLY with exactly x y z nx ny nz (float) red green blue (uchar).");
                // The header's count is checked against the bytes that follow it before anything is allocated: a header
                // claiming 2 billion points over a few bytes is a truncated (or hostile) file, not an out-of-memory.
                var available = file.Length - file.Position;
                if (available < (long)count * VertexBytes)
                    throw Problem(path, "is truncated: its header declares " + count + " points (" + ((long)count * VertexBytes) + " bytes), but only " +
                                        available + " bytes follow the header.");
                var points = new List<CloudPoint>(count);
                using (var reader = new BinaryReader(file, Encoding.ASCII, leaveOpen: true))
                {
                    for (var i = 0; i < count; i++)
                    {
                        var p = new Vector3d(reader.ReadSingle(), reader.ReadSingle(), reader.ReadSingle());
                        var n = new Vector3d(reader.ReadSingle(), reader.ReadSingle(), reader.ReadSingle());
                        points.Add(new CloudPoint(p, n, reader.ReadByte(), reader.ReadByte(), reader.ReadByte()));
                    }
                }
                return points;
            }
        }

        static string ReadHeader(Stream stream)
        {
            var header = new StringBuilder();
            const string end = "end_header\n";
            while (header.Length < 4096)
            {
                var b = stream.ReadByte();
                if (b < 0) break;
                header.Append((char)b);
                if (header.Length >= end.Length && header.ToString(header.Length - end.Length, end.Length) == end)
                    return header.ToString();
            }
            return header.ToString();
        }

        /// <summary>The header without its <c>comment</c> lines (3DGS's storePly writes none, ours one).</summary>
        static string WithoutComments(string header) =>
            string.Join("\n", header.Split('\n').Where(line => !line.StartsWith("comment ", StringComparison.Ordinal) && line != "comment"));

        static int ParseCount(string header, string path)
        {
            const string key = "element vertex ";
            var start = header.IndexOf(key, StringComparison.Ordinal);
            if (start < 0) throw Problem(path, "has no vertex element.");
            var stop = header.IndexOf('\n', start);
            if (stop < 0 || !int.TryParse(header.Substring(start + key.Length, stop - start - key.Length), System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out var count))
                throw Problem(path, "has an unreadable vertex count.");
            return count;
        }

        static InvalidParameterException Problem(string path, string reason) =>
            new InvalidParameterException(new[] { new ValidationProblem("points3d.ply", path, reason, "Re-export the point cloud with this plugin, or remove the file.") });
    }
}
