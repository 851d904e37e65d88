using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The header of a PLY file (Greg Turk's format as MeshLab, Open3D and 3DGS write it): the lines from <c>ply</c> to
    /// <c>end_header</c>, then what they declare — the format and the elements with their properties, in order. The
    /// one PLY header reader: <see cref="PlyReader"/> (points3d.ply), <see cref="PlyMesh"/> (reconstructions and the
    /// geometry pack's meshes) and <see cref="PointCloudOwnership"/> all read through it, each with its own limits and
    /// messages. The data after the header is read with <see cref="PlyValueReader"/>.
    /// </summary>
    public sealed class PlyHeader
    {
        public const string EndLine = "end_header";

        PlyHeader(string text, List<string> lines, bool ended, bool cutShort)
        {
            Text = text;
            Lines = lines;
            Ended = ended;
            CutShort = cutShort;
        }

        /// <summary>Every byte read, one character each, line ends included.</summary>
        public string Text { get; }

        /// <summary>The complete lines read, without their line end (<c>\n</c>, or <c>\r\n</c> as Windows tools write).</summary>
        public IReadOnlyList<string> Lines { get; }

        /// <summary>Whether the last line read is <c>end_header</c>: the stream stands at the first byte of the data.</summary>
        public bool Ended { get; }

        /// <summary>Whether the file ended before <c>end_header</c>.</summary>
        public bool CutShort { get; }

        /// <summary>
        /// Reads up to and including the <c>end_header</c> line, stopping earlier at the end of the file, after
        /// <paramref name="maxBytes"/> bytes or after <paramref name="maxLines"/> lines: a caller that refuses a
        /// header past its limit reads no further than that (byte by byte: the data starts right after the header).
        /// </summary>
        public static PlyHeader Read(Stream stream, int maxBytes = int.MaxValue, int maxLines = int.MaxValue)
        {
            var text = new StringBuilder();
            var lines = new List<string>();
            var line = new StringBuilder();
            while (text.Length < maxBytes && lines.Count < maxLines)
            {
                var b = stream.ReadByte();
                if (b < 0) return new PlyHeader(text.ToString(), lines, false, true);
                text.Append((char)b);
                if (b != '\n')
                {
                    line.Append((char)b);
                    continue;
                }
                var complete = line.ToString().TrimEnd('\r');
                line.Clear();
                lines.Add(complete);
                if (complete == EndLine) return new PlyHeader(text.ToString(), lines, true, false);
            }
            return new PlyHeader(text.ToString(), lines, false, false);
        }

        /// <summary>The <c>format</c> line's first word (ascii, binary_little_endian, binary_big_endian), or null.</summary>
        public string Format { get; private set; }

        /// <summary>The elements the header declares, in file order.</summary>
        public IReadOnlyList<PlyElement> Elements { get; private set; } = Array.Empty<PlyElement>();

        /// <summary>
        /// The fewest bytes of data that can hold what <see cref="Elements"/> declare, compared with what follows the
        /// header before anything is allocated (a 500 M-vertex claim over a few bytes is a truncated or hostile file,
        /// not an out-of-memory). Binary: every scalar's size, a list at least its count; ascii: at least one byte per
        /// value. In doubles, so that no count overflows (the answer only needs to exceed the file's length).
        /// </summary>
        /// <param name="size">The bytes of a scalar type (<see cref="PlyValueReader.SizeOf"/>, which refuses an unknown type).</param>
        public double MinimumDataBytes(Func<string, int> size)
        {
            var ascii = Format == "ascii";
            double total = 0;
            foreach (var element in Elements)
            {
                double perElement = 0;
                foreach (var property in element.Properties)
                    perElement += ascii ? 1 : size(property.IsList ? property.CountType : property.Type);
                total += perElement * element.Count;
            }
            return total;
        }

        /// <summary>
        /// Reads <see cref="Format"/> and <see cref="Elements"/> from the lines after the first; comments, <c>obj_info</c>
        /// and unknown lines are skipped. Returns the first <c>element</c> or <c>property</c> line it cannot read, or null:
        /// an element count must be a whole number from 0 to <see cref="long.MaxValue"/> (<c>abc</c>, <c>-5</c> or 20
        /// digits used to escape as "unexpected FormatException").
        /// </summary>
        public string Declare()
        {
            var elements = new List<PlyElement>();
            for (var i = 1; i < Lines.Count; i++)
            {
                var l = Lines[i];
                var parts = l.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries);
                if (parts.Length == 0 || parts[0] == "comment" || parts[0] == "obj_info") continue;
                if (parts[0] == "format" && parts.Length >= 2) Format = parts[1];
                else if (parts[0] == "element")
                {
                    if (parts.Length != 3 || !long.TryParse(parts[2], NumberStyles.None, CultureInfo.InvariantCulture, out var count))
                    {
                        Elements = elements;
                        return l;
                    }
                    elements.Add(new PlyElement(parts[1], count));
                }
                else if (parts[0] == "property" && elements.Count > 0)
                {
                    if (parts.Length == 5 && parts[1] == "list") elements[elements.Count - 1].Properties.Add(new PlyProperty(parts[4], parts[3], parts[2]));
                    else if (parts.Length == 3) elements[elements.Count - 1].Properties.Add(new PlyProperty(parts[2], parts[1], null));
                    else
                    {
                        Elements = elements;
                        return l;
                    }
                }
            }
            Elements = elements;
            return null;
        }
    }

    /// <summary>One <c>element &lt;name&gt; &lt;count&gt;</c> of a PLY header and its properties.</summary>
    public sealed class PlyElement
    {
        public PlyElement(string name, long count)
        {
            Name = name;
            Count = count;
        }

        public string Name { get; }
        public long Count { get; }
        public List<PlyProperty> Properties { get; } = new List<PlyProperty>();
    }

    /// <summary><c>property &lt;type&gt; &lt;name&gt;</c>, or <c>property list &lt;count type&gt; &lt;type&gt; &lt;name&gt;</c>.</summary>
    public sealed class PlyProperty
    {
        public PlyProperty(string name, string type, string countType)
        {
            Name = name;
            Type = type;
            CountType = countType;
        }

        public string Name { get; }

        /// <summary>The scalar type of the value, or of a list's entries.</summary>
        public string Type { get; }

        /// <summary>A list's count type; null for a scalar property.</summary>
        public string CountType { get; }

        public bool IsList => CountType != null;
    }
}
