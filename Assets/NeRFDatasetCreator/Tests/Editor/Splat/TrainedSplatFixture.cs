using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A dataset and a trained 3DGS model folder of it for the <i>Place trained splat</i> tests: the tool's own demo dataset,
    /// and point_cloud/iteration_N/point_cloud.ply with 3DGS's property list (graphdeco gaussian_model.py construct_list_of_attributes:
    /// x y z nx ny nz f_dc_0..2 f_rest_0..44 opacity scale_0..2 rot_0..3, binary little-endian floats) whose centres are given.
    /// </summary>
    public static class TrainedSplatFixture
    {
        public static string Dataset(string root)
        {
            var folder = Path.Combine(root, "dataset");
            var demo = ToolTranscript.Run("demo", folder, "--views", "4", "--size", "32");
            Assert.That(demo.Succeeded, Is.True, string.Join("\n", demo.Lines));
            return folder;
        }

        /// <summary>A 3DGS model folder with iterations 7000 and 30000 (the latter placed), centres in the dataset's frame.</summary>
        public static string ThreeDgsModel(string root, IReadOnlyList<Vector3d> centres)
        {
            var model = Path.Combine(root, "model");
            foreach (var iteration in new[] { 7000, 30000 })
            {
                var folder = Path.Combine(model, "point_cloud", "iteration_" + iteration);
                Directory.CreateDirectory(folder);
                WritePly(Path.Combine(folder, "point_cloud.ply"), centres);
            }
            return model;
        }

        public static string PlyOf(string model) => Path.Combine(model, "point_cloud", "iteration_30000", "point_cloud.ply");

        static void WritePly(string path, IReadOnlyList<Vector3d> centres)
        {
            var names = new List<string> { "x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2" };
            names.AddRange(Enumerable.Range(0, 45).Select(i => "f_rest_" + i));
            names.AddRange(new[] { "opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3" });
            using (var stream = File.Create(path))
            using (var writer = new BinaryWriter(stream))
            {
                var header = "ply\nformat binary_little_endian 1.0\nelement vertex " + centres.Count + "\n" +
                             string.Concat(names.Select(n => "property float " + n + "\n")) + "end_header\n";
                writer.Write(Encoding.ASCII.GetBytes(header));
                foreach (var c in centres)
                    foreach (var n in names)
                        writer.Write(n == "x" ? (float)c.X : n == "y" ? (float)c.Y : n == "z" ? (float)c.Z
                            : n == "opacity" ? 4f : n == "rot_0" ? 1f : n.StartsWith("scale_") ? -4f : 0f);
            }
        }
    }
}
