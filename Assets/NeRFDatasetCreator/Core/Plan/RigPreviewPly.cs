using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// An ASCII PLY of the planned rig in the output frame (the frame of the transforms files): per camera its
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

        public static string Write(CapturePlan plan)
        {
            var vertices = new List<string>();
            var edges = new List<string>();
            // Output units: the camera distance times the normalisation's scale.
            var depth = FrustumDepthFraction * plan.Distance * plan.Normalisation.Scale;
            var halfW = depth * Math.Tan(plan.Intrinsics.CameraAngleX / 2);
            var halfH = depth * Math.Tan(plan.Intrinsics.CameraAngleY / 2);
            vertices.Add(Vertex(plan.Normalisation.ApplyToUnityPoint(plan.Target.Centre), TargetColour));
            foreach (var view in plan.Views)
            {
                var colour = ColourOf(view.Split);
                var m = view.TransformMatrix;
                var centre = vertices.Count;
                vertices.Add(Vertex(m.Translation, colour));
                // Image corners in OpenGL camera space: +X right, +Y up, looking along −Z.
                foreach (var corner in new[] { new Vector3d(-halfW, halfH, -depth), new Vector3d(halfW, halfH, -depth), new Vector3d(halfW, -halfH, -depth), new Vector3d(-halfW, -halfH, -depth) })
                    vertices.Add(Vertex(m.MultiplyPoint(corner), colour));
                for (var k = 0; k < 4; k++)
                {
                    edges.Add(Edge(centre, centre + 1 + k, colour));
                    edges.Add(Edge(centre + 1 + k, centre + 1 + (k + 1) % 4, colour));
                }
            }
            var sb = new StringBuilder();
            sb.Append("ply\nformat ascii 1.0\ncomment ").Append(PluginInfo.Name).Append(" rig preview: train sky blue, val orange, test reddish purple, target white; output (Blender) frame\n");
            sb.Append("element vertex ").Append(vertices.Count.ToString(CultureInfo.InvariantCulture)).Append('\n');
            sb.Append("property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n");
            sb.Append("element edge ").Append(edges.Count.ToString(CultureInfo.InvariantCulture)).Append('\n');
            sb.Append("property int vertex1\nproperty int vertex2\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n");
            sb.Append("end_header\n");
            foreach (var v in vertices) sb.Append(v).Append('\n');
            foreach (var e in edges) sb.Append(e).Append('\n');
            return sb.ToString(); // numbers went through Number(), Byte() and invariant counts
        }

        static string Vertex(Vector3d p, byte[] c) =>
            string.Join(" ", Number(p.X), Number(p.Y), Number(p.Z), Byte(c[0]), Byte(c[1]), Byte(c[2]));

        static string Edge(int a, int b, byte[] c) =>
            string.Join(" ", a.ToString(CultureInfo.InvariantCulture), b.ToString(CultureInfo.InvariantCulture), Byte(c[0]), Byte(c[1]), Byte(c[2]));

        // PLY "float" is 32-bit; 9 significant digits round-trip a float.
        static string Number(double v) => ((float)v).ToString("G9", CultureInfo.InvariantCulture);

        static string Byte(byte b) => b.ToString(CultureInfo.InvariantCulture);

        static byte[] Bytes(RgbaColor c) => new[] { ToByte(c.R), ToByte(c.G), ToByte(c.B) };

        static byte ToByte(float component) => (byte)Math.Round(Math.Max(0, Math.Min(1, component)) * 255);
    }
}
