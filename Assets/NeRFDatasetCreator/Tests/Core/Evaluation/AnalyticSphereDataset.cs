using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A Blender-format dataset rendered analytically: the test suite's <see cref="AnalyticScene"/> holding one sphere of
    /// radius <see cref="Radius"/> at the output origin, seen by cameras at distance 4 looking at it (OpenGL cameras, +Z
    /// up), written by hand (not through Core's writers: the evaluation's oracle). Each pixel's ray through its centre is
    /// intersected with the sphere exactly: colour = 0.5 + 0.5·n (RGBA, background transparent), z-depth (16-bit thousandths), normal
    /// (8-bit, output frame) and mask PNGs, and <c>geometry/target_mesh.ply</c> a UV sphere of the same radius. Renders in
    /// each trainer's layout are made from the same pixels (<see cref="Render"/>), optionally perturbed.
    /// </summary>
    static class AnalyticSphereDataset
    {
        public const double Radius = 1.0;
        public const double Distance = 4.0;
        public const double CameraAngleX = 0.6911112070083618;

        public sealed class View
        {
            public Matrix4x4d CameraToWorld;
            public byte[] Rgba;
            public ushort[] Depth;
            public byte[] Normals;
            public byte[] Mask;
        }

        public static Matrix4x4d LookAtOrigin(Vector3d eye)
        {
            var forward = (Vector3d.Zero - eye).Normalized();
            var right = Vector3d.Cross(forward, Vector3d.UnitZ).Normalized();
            var up = Vector3d.Cross(right, forward);
            return Matrix4x4d.FromColumns(right, up, -forward, eye);
        }

        /// <summary>The camera centre of view <paramref name="i"/> of <paramref name="count"/>: around the sphere, elevations alternating ±30°.</summary>
        public static Vector3d Eye(int i, int count, double offset)
        {
            var azimuth = 2 * Math.PI * (i + offset) / count;
            var elevation = (i % 2 == 0 ? 1 : -1) * Math.PI / 6;
            return new Vector3d(Math.Cos(elevation) * Math.Cos(azimuth), Math.Cos(elevation) * Math.Sin(azimuth), Math.Sin(elevation)) * Distance;
        }

        static readonly AnalyticScene Sphere = AnalyticScene.OneSphere(Vector3d.Zero, Radius);

        public static View RenderView(Matrix4x4d c2w, int width, int height)
        {
            var focal = 0.5 * width / Math.Tan(0.5 * CameraAngleX);
            var view = new View { CameraToWorld = c2w, Rgba = new byte[width * height * 4], Depth = new ushort[width * height], Normals = new byte[width * height * 3], Mask = new byte[width * height] };
            var origin = c2w.Translation;
            for (var v = 0; v < height; v++)
                for (var u = 0; u < width; u++)
                {
                    var dirCam = new Vector3d((u + 0.5 - width / 2.0) / focal, -(v + 0.5 - height / 2.0) / focal, -1);
                    var d = c2w.MultiplyVector(dirCam);
                    // t is the z-depth (dirCam has z = −1); the camera is outside the sphere, so the hit's normal faces it.
                    if (!Sphere.Trace(origin, d, 0, out var t, out var n, out _, out _)) continue;
                    var i = v * width + u;
                    view.Rgba[4 * i] = Byte(0.5 + 0.5 * n.X);
                    view.Rgba[4 * i + 1] = Byte(0.5 + 0.5 * n.Y);
                    view.Rgba[4 * i + 2] = Byte(0.5 + 0.5 * n.Z);
                    view.Rgba[4 * i + 3] = 255;
                    view.Depth[i] = (ushort)Math.Round(t * 1000);
                    view.Normals[3 * i] = Byte(n.X * 0.5 + 0.5);
                    view.Normals[3 * i + 1] = Byte(n.Y * 0.5 + 0.5);
                    view.Normals[3 * i + 2] = Byte(n.Z * 0.5 + 0.5);
                    view.Mask[i] = 255;
                }
            return view;
        }

        static byte Byte(double v) => (byte)Math.Round(255 * Math.Max(0, Math.Min(1, v)));

        /// <summary>Writes the dataset (train and test splits; val empty) and returns the test views.</summary>
        public static List<View> Write(string folder, int width = 48, int height = 40, int train = 6, int test = 3, bool mesh = true)
        {
            Directory.CreateDirectory(folder);
            List<View> testViews = null;
            foreach (var (split, count, offset) in new[] { ("train", train, 0.0), ("val", 0, 0.25), ("test", test, 0.5) })
            {
                var views = new List<View>();
                Directory.CreateDirectory(Path.Combine(folder, split));
                var frames = new StringBuilder();
                for (var i = 0; i < count; i++)
                {
                    var view = RenderView(LookAtOrigin(Eye(i, count, offset)), width, height);
                    views.Add(view);
                    var stem = Path.Combine(folder, split, "r_" + i);
                    File.WriteAllBytes(stem + ".png", PngWriter.Encode(view.Rgba, width, height, PngPixelFormat.Rgba8));
                    File.WriteAllBytes(stem + "_depth_0000.png", PngWriter.EncodeGray16(view.Depth, width, height));
                    File.WriteAllBytes(stem + "_normal_0000.png", PngWriter.Encode(view.Normals, width, height, PngPixelFormat.Rgb8));
                    File.WriteAllBytes(stem + "_mask_0000.png", PngWriter.Encode(view.Mask, width, height, PngPixelFormat.Gray8));
                    if (i > 0) frames.Append(",\n");
                    var rows = view.CameraToWorld.ToRows();
                    frames.Append("    {\"file_path\": \"./").Append(split).Append("/r_").Append(i).Append("\", \"rotation\": 0.0, \"transform_matrix\": [");
                    for (var r = 0; r < 4; r++)
                    {
                        if (r > 0) frames.Append(", ");
                        frames.Append('[').Append(string.Join(", ", Array.ConvertAll(rows[r], x => x.ToString("R", CultureInfo.InvariantCulture)))).Append(']');
                    }
                    frames.Append("], \"depth_path\": \"./").Append(split).Append("/r_").Append(i).Append("_depth_0000.png\", \"normal_path\": \"./").Append(split).Append("/r_").Append(i)
                        .Append("_normal_0000.png\", \"mask_path\": \"./").Append(split).Append("/r_").Append(i).Append("_mask_0000.png\"}");
                }
                File.WriteAllText(Path.Combine(folder, "transforms_" + split + ".json"),
                    "{\n  \"camera_angle_x\": " + CameraAngleX.ToString("R", CultureInfo.InvariantCulture) + ",\n  \"w\": " + width + ", \"h\": " + height +
                    ",\n  \"integer_depth_scale\": 0.001,\n  \"frames\": [\n" + frames + "\n  ]\n}\n");
                if (split == "test") testViews = views;
            }
            if (mesh)
            {
                Directory.CreateDirectory(Path.Combine(folder, TargetMeshPly.Folder));
                TargetMeshPly.Write(Path.Combine(folder, TargetMeshPly.Folder, TargetMeshPly.FileName), new[] { UvSphere(Radius, 48, 96) });
            }
            return testViews;
        }

        /// <summary>
        /// Makes a split of a dataset <see cref="Write"/> wrote look like nerf_synthetic's: its frames name no pass files
        /// (no depth_path, normal_path, mask_path keys), and beside each image lie nerf_synthetic's own
        /// <c>r_&lt;i&gt;_depth_0000.png</c> and <c>r_&lt;i&gt;_normal_0000.png</c> — 8-bit RGBA pictures, not data — and no mask.
        /// </summary>
        public static void MakeNerfSyntheticStyle(string folder, string split, IReadOnlyList<View> views, int width, int height)
        {
            var path = Path.Combine(folder, "transforms_" + split + ".json");
            var json = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(path));
            foreach (Newtonsoft.Json.Linq.JObject frame in (Newtonsoft.Json.Linq.JArray)json["frames"])
            {
                frame.Remove("depth_path");
                frame.Remove("normal_path");
                frame.Remove("mask_path");
            }
            File.WriteAllText(path, json.ToString());
            for (var i = 0; i < views.Count; i++)
            {
                var stem = Path.Combine(folder, split, "r_" + i);
                File.WriteAllBytes(stem + "_depth_0000.png", PngWriter.Encode(views[i].Rgba, width, height, PngPixelFormat.Rgba8));
                File.WriteAllBytes(stem + "_normal_0000.png", PngWriter.Encode(views[i].Rgba, width, height, PngPixelFormat.Rgba8));
                File.Delete(stem + "_mask_0000.png");
            }
        }

        /// <summary>A UV sphere centred at the origin (<see cref="AnalyticSceneMeshes.UvSphere"/>).</summary>
        public static SurfaceMesh UvSphere(double radius, int rings, int segments, string name = "sphere") =>
            AnalyticSceneMeshes.UvSphere(radius, rings, segments, name);

        /// <summary>
        /// The test view composited on white as 8-bit RGB (what a model trained with a white background renders),
        /// with <paramref name="perturb"/> added to every red sample inside the sphere (clamped).
        /// </summary>
        public static byte[] Render(View view, int width, int height, int perturb)
        {
            var rgb = new byte[width * height * 3];
            for (var p = 0; p < width * height; p++)
            {
                var a = view.Rgba[4 * p + 3] / 255.0;
                for (var c = 0; c < 3; c++) rgb[3 * p + c] = (byte)Math.Round(view.Rgba[4 * p + c] * a + 255 * (1 - a));
                if (view.Mask[p] > 0) rgb[3 * p] = (byte)Math.Max(0, Math.Min(255, rgb[3 * p] + perturb));
            }
            return rgb;
        }
    }
}
