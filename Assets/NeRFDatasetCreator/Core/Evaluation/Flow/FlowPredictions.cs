using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The folder of a model's rendered motion that <c>evaluate --flow</c> reads: the dataset's own <c>flow/</c> layout
    /// (<see cref="FlowLayout"/>) without the leading <c>flow/</c> — <c>&lt;folder&gt;/&lt;video&gt;/flow_&lt;a&gt;_&lt;b&gt;.flo</c>
    /// (Middlebury .flo, (dx, dy) pixels from pixel centre (u + 0.5, v + 0.5) of frame a to frame b, x right, y down) and
    /// <c>&lt;folder&gt;/&lt;video&gt;/tracks_&lt;q&gt;.npz</c> with <c>xy</c> (T, N, 2): the model's position of our query
    /// points (the truth file's <c>query_xy</c>, in its order) in every frame, continuous pixel coordinates (centre at + 0.5).
    /// </summary>
    public static class FlowPredictions
    {
        /// <summary>A path of ours (<c>flow/train/flow_0000_0001.flo</c>) as the prediction folder holds it (<c>train/flow_0000_0001.flo</c>).</summary>
        public static string Relative(string ours) =>
            ours.StartsWith(FlowLayout.Folder + "/", StringComparison.Ordinal) ? ours.Substring(FlowLayout.Folder.Length + 1) : ours;

        public static string Full(string folder, string ours) => Path.Combine(folder, Relative(ours).Replace('/', Path.DirectorySeparatorChar));

        /// <summary>An .npz's array <paramref name="key"/> (entry <c>key.npy</c>); an <see cref="InvalidDataException"/> naming the file when absent or unreadable.</summary>
        public static NpyReader.NpyArray NpzArray(string path, string key)
        {
            try
            {
                // ZipArchive over the file (as NumpyFiles writes), not ZipFile: one assembly fewer for Unity's profile.
                using (var file = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
                using (var zip = new ZipArchive(file, ZipArchiveMode.Read))
                {
                    var entry = zip.GetEntry(key + ".npy") ?? throw new InvalidDataException(path + " has no array '" + key + "' (entries: " + string.Join(", ", zip.Entries.Select(e => e.FullName)) + ").");
                    if (entry.Length > ReadableFile.MaxGeometryBytes) throw new InvalidDataException(path + ": '" + key + "' holds " + entry.Length + " bytes, more than any tracks array.");
                    using (var stream = entry.Open())
                    using (var memory = new MemoryStream())
                    {
                        stream.CopyTo(memory);
                        return NpyReader.Decode(memory.ToArray(), path + " '" + key + "'");
                    }
                }
            }
            catch (InvalidDataException e) when (!e.Message.StartsWith(path, StringComparison.Ordinal)) { throw new InvalidDataException(path + " is not a readable .npz: " + e.Message); }
        }

        /// <summary>Whether an array has exactly <paramref name="shape"/>.</summary>
        public static bool Shaped(NpyReader.NpyArray array, params int[] shape) => array.Shape.SequenceEqual(shape);

        public static string ShapeText(IEnumerable<int> shape) => "(" + string.Join(", ", shape) + ")";
    }
}
