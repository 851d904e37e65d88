using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One of our <c>flow/&lt;video&gt;/tracks_&lt;q&gt;.npz</c> files read back (<see cref="FlowWriter.TracksNpz"/>): the
    /// query points' pixel centres, where each point is in every frame of the video (NaN behind the camera) and its
    /// <see cref="FlowState"/> there. Frame-major like <see cref="SurfaceTracks"/>: <c>Xy[(t·N + n)·2 + c]</c>.
    /// </summary>
    public sealed class FlowTracksFile
    {
        public int Frames { get; private set; }
        public int Points { get; private set; }
        public float[] QueryXy { get; private set; }
        public float[] Xy { get; private set; }
        public byte[] State { get; private set; }

        public float X(int frame, int point) => Xy[2 * (frame * Points + point)];
        public float Y(int frame, int point) => Xy[2 * (frame * Points + point) + 1];
        public FlowState StateAt(int frame, int point) => (FlowState)State[frame * Points + point];

        /// <summary>Reads <paramref name="path"/>; a missing key or a shape that disagrees is an <see cref="InvalidDataException"/> naming the file.</summary>
        public static FlowTracksFile Read(string path)
        {
            var name = Path.GetFileName(path);
            var arrays = new Dictionary<string, byte[]>();
            using (var zip = new ZipArchive(File.OpenRead(path), ZipArchiveMode.Read))
                foreach (var entry in zip.Entries)
                    using (var s = entry.Open())
                    using (var copy = new MemoryStream())
                    {
                        s.CopyTo(copy);
                        arrays[entry.FullName.EndsWith(".npy", StringComparison.Ordinal) ? entry.FullName.Substring(0, entry.FullName.Length - 4) : entry.FullName] = copy.ToArray();
                    }
            byte[] Array(string key) => arrays.TryGetValue(key, out var bytes) ? bytes : throw new InvalidDataException(name + " has no \"" + key + "\" array.");
            var query = NpyReader.Decode(Array("query_xy"), name + ":query_xy");
            var xy = NpyReader.Decode(Array("xy"), name + ":xy");
            var state = UInt8(Array("state"), name + ":state", out var stateShape);
            if (query.Shape.Length != 2 || query.Shape[1] != 2 || xy.Shape.Length != 3 || xy.Shape[2] != 2 || xy.Shape[1] != query.Shape[0]
                || stateShape.Length != 2 || stateShape[0] != xy.Shape[0] || stateShape[1] != xy.Shape[1])
                throw new InvalidDataException(name + ": query_xy, xy and state do not have the shapes (N, 2), (T, N, 2), (T, N).");
            return new FlowTracksFile { Frames = xy.Shape[0], Points = xy.Shape[1], QueryXy = query.Values, Xy = xy.Values, State = state };
        }

        /// <summary>A version-1 .npy of '|u1' values in C order, as <see cref="NumpyFiles.UInt8Array"/> writes it.</summary>
        static byte[] UInt8(byte[] bytes, string name, out int[] shape)
        {
            if (bytes.Length < 10 || bytes[0] != 0x93 || Encoding.ASCII.GetString(bytes, 1, 5) != "NUMPY" || bytes[6] != 1)
                throw new InvalidDataException(name + " is not a version-1 NumPy array.");
            var headerLength = bytes[8] | (bytes[9] << 8);
            if (10 + headerLength > bytes.Length) throw new InvalidDataException(name + " is cut short.");
            var header = Encoding.ASCII.GetString(bytes, 10, headerLength);
            if (!header.Contains("'descr': '|u1'") || !header.Contains("'fortran_order': False"))
                throw new InvalidDataException(name + " is not a C-order uint8 array.");
            var open = header.IndexOf('(', header.IndexOf("'shape'", StringComparison.Ordinal));
            var close = header.IndexOf(')', open);
            var dims = new List<int>();
            foreach (var part in header.Substring(open + 1, close - open - 1).Split(','))
                if (part.Trim().Length > 0) dims.Add(int.Parse(part.Trim(), System.Globalization.CultureInfo.InvariantCulture));
            shape = dims.ToArray();
            long count = 1;
            foreach (var d in shape) count *= d;
            if (10 + headerLength + count != bytes.Length) throw new InvalidDataException(name + " holds " + (bytes.Length - 10 - headerLength) + " bytes of data, not the " + count + " its shape needs.");
            var values = new byte[count];
            Buffer.BlockCopy(bytes, 10 + headerLength, values, 0, (int)count);
            return values;
        }
    }
}
