using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A binary little-endian PLY of the planned rig in the output frame (the frame of the transforms files): per camera its
    /// centre and a small frustum pyramid (4 edges to the image corners and the image rectangle), plus a marker
    /// at the target; vertices and edges coloured by split in the Scene-view preview's palette (<see cref="SplitColors"/>:
    /// train sky blue, val orange, test reddish purple; target white), so both previews read the same way.
    /// MeshLab and Blender read <c>element vertex</c> with <c>red green blue</c> and <c>element edge</c>.
    /// </summary>
    public static class RigPreviewPly
    {
        public static readonly byte[] TrainColour = Bytes(SplitColors.Train);
        public static readonly byte[] ValColour = Bytes(SplitColors.Val);
        public static readonly byte[] TestColour = Bytes(SplitColors.Test);
        public static readonly byte[] TargetColour = { 255, 255, 255 };

        /// <summary>The frustum drawn for each camera reaches this fraction of the camera distance.</summary>
        public const double FrustumDepthFraction = 0.15;

        public static byte[] ColourOf(DatasetSplit split) =>
            split == DatasetSplit.Train ? TrainColour : split == DatasetSplit.Val ? ValColour : TestColour;

        /// <summary>Bytes per vertex record: float x y z, uchar red green blue.</summary>
        public const int BytesPerVertex = 3 * 4 + 3;

        /// <summary>Bytes per edge record: int vertex1 vertex2, uchar red green blue.</summary>
        public const int BytesPerEdge = 2 * 4 + 3;

        public static string Header(int vertexCount, int edgeCount) =>
            "ply\nformat binary_little_endian 1.0\ncomment " + PluginInfo.Name +
            " rig preview: train sky blue, val orange, test reddish purple, target white; output (Blender) frame\n" +
            "element vertex " + vertexCount.ToString(CultureInfo.InvariantCulture) + "\n" +
            "property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n" +
            "element edge " + edgeCount.ToString(CultureInfo.InvariantCulture) + "\n" +
            "property int vertex1\nproperty int vertex2\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n" +
            "end_header\n";

        /// <summary>
        /// Streams the PLY to <paramref name="stream"/>: binary little-endian (a quarter of the ASCII size, and no text
        /// to build: 300 000 views are 49 MB written straight from the plan, in constant memory). Vertex 0 is the
        /// target; camera <c>i</c>'s centre is vertex 1 + 5i, its image corners the next four; its 8 edges follow the
        /// same order as the vertices.
        /// </summary>
        public static void Write(CapturePlan plan, Stream stream)
        {
            var views = plan.Views;
            var header = Encoding.ASCII.GetBytes(Header(1 + 5 * views.Count, 8 * views.Count));
            stream.Write(header, 0, header.Length);
            // Output units: the camera distance times the normalisation's scale.
            var depth = FrustumDepthFraction * plan.Distance * plan.Normalisation.Scale;
            var halfW = depth * Math.Tan(plan.Intrinsics.CameraAngleX / 2);
            var halfH = depth * Math.Tan(plan.Intrinsics.CameraAngleY / 2);
            // Image corners in OpenGL camera space: +X right, +Y up, looking along −Z.
            var corners = new[] { new Vector3d(-halfW, halfH, -depth), new Vector3d(halfW, halfH, -depth), new Vector3d(halfW, -halfH, -depth), new Vector3d(-halfW, -halfH, -depth) };
            // BinaryWriter is little-endian on every platform, as the header says.
            using (var writer = new BinaryWriter(stream, Encoding.ASCII, leaveOpen: true))
            {
                Vertex(writer, plan.Normalisation.ApplyToUnityPoint(plan.Target.Centre), TargetColour);
                foreach (var view in views)
                {
                    var colour = ColourOf(view.Split);
                    var m = view.TransformMatrix;
                    Vertex(writer, m.Translation, colour);
                    foreach (var corner in corners) Vertex(writer, m.MultiplyPoint(corner), colour);
                }
                // A plan lists its views split by split; their counts give each edge's colour without making the views again.
                var i = 0;
                foreach (var split in DatasetSplits.All)
                {
                    var colour = ColourOf(split);
                    for (var end = i + plan.ViewsOf(split).Count; i < end; i++)
                    {
                        var centre = 1 + 5 * i;
                        for (var k = 0; k < 4; k++)
                        {
                            Edge(writer, centre, centre + 1 + k, colour);
                            Edge(writer, centre + 1 + k, centre + 1 + (k + 1) % 4, colour);
                        }
                    }
                }
            }
        }

        /// <summary>The whole file in memory (tests, small plans); <see cref="Write(CapturePlan, Stream)"/> streams it.</summary>
        public static byte[] Encode(CapturePlan plan)
        {
            using (var memory = new MemoryStream())
            {
                Write(plan, memory);
                return memory.ToArray();
            }
        }

        static void Vertex(BinaryWriter w, Vector3d p, byte[] c)
        {
            w.Write((float)p.X);
            w.Write((float)p.Y);
            w.Write((float)p.Z);
            w.Write(c, 0, 3);
        }

        static void Edge(BinaryWriter w, int a, int b, byte[] c)
        {
            w.Write(a);
            w.Write(b);
            w.Write(c, 0, 3);
        }

        static byte[] Bytes(RgbaColor c) => new[] { ToByte(c.R), ToByte(c.G), ToByte(c.B) };

        static byte ToByte(float component) => (byte)Math.Round(Math.Max(0, Math.Min(1, component)) * 255);
    }
}
