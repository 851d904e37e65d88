using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

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
            using (var file = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
            {
                // The header is compared as text with the one PlyWriter writes, so it is read no further than a header can be long.
                var header = PlyHeader.Read(file, maxBytes: MaxHeaderBytes).Text;
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
                var values = new PlyValueReader(file, "binary_little_endian", reason => Problem(path, reason));
                const PlyScalar f = PlyScalar.Float32, u = PlyScalar.UInt8;
                for (var i = 0; i < count; i++)
                {
                    var p = new Vector3d(values.Read(f), values.Read(f), values.Read(f));
                    var n = new Vector3d(values.Read(f), values.Read(f), values.Read(f));
                    points.Add(new CloudPoint(p, n, (byte)values.Read(u), (byte)values.Read(u), (byte)values.Read(u)));
                }
                return points;
            }
        }

        /// <summary>Longer than any header <see cref="PlyWriter"/> or 3DGS's storePly writes.</summary>
        const int MaxHeaderBytes = 4096;

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
