using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>points3d.ply</c> exactly as 3D Gaussian Splatting's <c>storePly</c> writes it with plyfile and
    /// <c>fetchPly</c> reads it: binary little-endian, one <c>vertex</c> element with float x y z nx ny nz and uchar
    /// red green blue (27 bytes per vertex), plus one header comment (<see cref="Signature"/>) that marks the file as
    /// this plugin's: plyfile and Open3D skip comments, and the comment with the SHA-256 recorded in
    /// dataset_config.json (<see cref="PointCloudRecord"/>) tells our cloud from the random one 3DGS writes under the
    /// same name. nerfstudio reads the same file through Open3D.
    /// </summary>
    public static class PlyWriter
    {
        public const int BytesPerVertex = 6 * 4 + 3;

        /// <summary>The header comment of every cloud this plugin samples (after "comment ").</summary>
        public const string Signature = PluginInfo.Name + ": points sampled on the target's surface, output frame; SHA-256 in dataset_config.json";

        public static string Header(int vertexCount) =>
            "ply\n" +
            "format binary_little_endian 1.0\n" +
            "comment " + Signature + "\n" +
            "element vertex " + vertexCount.ToString(CultureInfo.InvariantCulture) + "\n" +
            "property float x\n" +
            "property float y\n" +
            "property float z\n" +
            "property float nx\n" +
            "property float ny\n" +
            "property float nz\n" +
            "property uchar red\n" +
            "property uchar green\n" +
            "property uchar blue\n" +
            "end_header\n";

        public static void Write(Stream stream, IReadOnlyList<CloudPoint> points)
        {
            var header = Encoding.ASCII.GetBytes(Header(points.Count));
            stream.Write(header, 0, header.Length);
            // BinaryWriter is little-endian on every platform, as the header promises.
            using (var writer = new BinaryWriter(stream, Encoding.ASCII, leaveOpen: true))
            {
                foreach (var p in points)
                {
                    writer.Write((float)p.Position.X);
                    writer.Write((float)p.Position.Y);
                    writer.Write((float)p.Position.Z);
                    writer.Write((float)p.Normal.X);
                    writer.Write((float)p.Normal.Y);
                    writer.Write((float)p.Normal.Z);
                    writer.Write(p.Red);
                    writer.Write(p.Green);
                    writer.Write(p.Blue);
                }
            }
        }

        public static void Write(string path, IReadOnlyList<CloudPoint> points)
        {
            using (var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write))
                Write(file, points);
        }
    }
}
