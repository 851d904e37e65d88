using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Middlebury's <c>.flo</c> optical-flow file, the one flow tools read (RAFT's <c>frame_utils.readFlow</c>, flowiz,
    /// OpenCV's <c>readOpticalFlow</c>): the float 202021.25 (the bytes "PIEH"), int32 width, int32 height, then
    /// width × height pairs of float32 (Δx, Δy), rows top first, all little-endian (Middlebury's flow-code
    /// <c>flowIO.cpp</c>, WriteFlowFile; citations in Documentation~/maintainers/flow.md). This plugin writes NaN where a
    /// pixel has no flow (no surface, or the point behind the other camera).
    /// </summary>
    public static class FloFile
    {
        /// <summary>The tag, 202021.25 as a little-endian float: the ASCII bytes "PIEH".</summary>
        public const float Tag = 202021.25f;

        public const string Extension = ".flo";

        /// <param name="flow">(Δx, Δy) per pixel, rows top first.</param>
        public static byte[] Encode(float[] flow, int width, int height)
        {
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), width + "×" + height, "A flow image has at least one pixel.");
            if (flow == null || flow.LongLength != 2L * width * height) throw new ArgumentException("Two floats per pixel are needed.", nameof(flow));
            var bytes = new byte[12 + 8L * width * height];
            Put(bytes, 0, BitConverter.ToInt32(BitConverter.GetBytes(Tag), 0));
            Put(bytes, 4, width);
            Put(bytes, 8, height);
            for (long i = 0; i < flow.LongLength; i++) Put(bytes, 12 + 4 * i, BitConverter.ToInt32(BitConverter.GetBytes(flow[i]), 0));
            return bytes;
        }

        /// <summary>Reads a .flo file's size and flow; a bad tag, size or length is an <see cref="InvalidDataException"/> naming the file.</summary>
        public static float[] Decode(byte[] bytes, string name, out int width, out int height)
        {
            if (bytes == null || bytes.Length < 12) throw new InvalidDataException(name + " is not a .flo file: shorter than its 12-byte header.");
            if (BitConverter.ToSingle(Le(bytes, 0), 0) != Tag) throw new InvalidDataException(name + " is not a .flo file: it does not start with the tag \"PIEH\" (202021.25).");
            width = BitConverter.ToInt32(Le(bytes, 4), 0);
            height = BitConverter.ToInt32(Le(bytes, 8), 0);
            if (width < 1 || height < 1 || width > 1 << 16 || height > 1 << 16)
                throw new InvalidDataException(name + " states a flow image of " + width + " × " + height + " pixels.");
            var expected = 12 + 8L * width * height;
            if (bytes.LongLength != expected)
                throw new InvalidDataException(name + " holds " + bytes.LongLength + " bytes, not the " + expected + " of a " + width + " × " + height + " flow image.");
            var flow = new float[2L * width * height];
            for (long i = 0; i < flow.LongLength; i++) flow[i] = BitConverter.ToSingle(Le(bytes, 12 + 4 * i), 0);
            return flow;
        }

        public static float[] Read(string path, out int width, out int height) => Decode(File.ReadAllBytes(path), Path.GetFileName(path), out width, out height);

        static void Put(byte[] bytes, long at, int value)
        {
            bytes[at] = (byte)value;
            bytes[at + 1] = (byte)(value >> 8);
            bytes[at + 2] = (byte)(value >> 16);
            bytes[at + 3] = (byte)(value >> 24);
        }

        // The 4 bytes at `at` in the machine's order (little-endian on every platform Unity and .NET run on today).
        static byte[] Le(byte[] bytes, long at)
        {
            var b = new[] { bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3] };
            if (!BitConverter.IsLittleEndian) Array.Reverse(b);
            return b;
        }
    }
}
