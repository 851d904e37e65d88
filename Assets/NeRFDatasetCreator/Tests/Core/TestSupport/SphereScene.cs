using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The independent oracle of the COLMAP track tests, and the one test scene besides <see cref="AnalyticScene"/> (whose
    /// ray–sphere solver it casts its rays through): coloured spheres in the output world, rendered exactly — one ray
    /// through each pixel centre, the nearest sphere hit — and written by hand, not through Core's writers, into the
    /// files a capture writes (output-format.md): RGBA, 16-bit depth PNG of
    /// round(z·1000) (z along the camera axis, 0 = nothing), 8-bit mask (255 = covered, edge pixels the covered
    /// fraction of 2×2 sub-samples), and a points3d.ply of points sampled uniformly by area with exact normals,
    /// recorded in dataset_config.json so that convert takes it as the target's surface. Independent of Core's
    /// COLMAP code: the tests compare Core's tracks with this scene's own ray casts. Also used by
    /// Tests/Benchmarks (linked) for the tracks benchmark.
    /// </summary>
    sealed class SphereScene
    {
        public readonly struct Sphere
        {
            public Sphere(Vector3d centre, double radius, byte red, byte green, byte blue)
            {
                Centre = centre; Radius = radius; Red = red; Green = green; Blue = blue;
            }

            public Vector3d Centre { get; }
            public double Radius { get; }
            public byte Red { get; }
            public byte Green { get; }
            public byte Blue { get; }
        }

        public SphereScene(params Sphere[] spheres)
        {
            Spheres = spheres;
            _scene = new AnalyticScene();
            foreach (var sphere in spheres)
                _scene.Spheres.Add(new AnalyticScene.Sphere { Centre = sphere.Centre, Radius = sphere.Radius, Colour = new[] { sphere.Red / 255.0, sphere.Green / 255.0, sphere.Blue / 255.0 } });
        }

        readonly AnalyticScene _scene;

        public Sphere[] Spheres { get; }

        /// <summary>Two objects, the small one hiding part of the big one from +x and hidden behind it from −x.</summary>
        public static SphereScene TwoSpheres() => new SphereScene(
            new Sphere(new Vector3d(0, 0, 0), 1.0, 200, 60, 40),
            new Sphere(new Vector3d(1.45, 0.1, 0.3), 0.35, 40, 90, 220));

        /// <summary>The nearest s &gt; 0 with origin + s·direction on a sphere (direction need not be unit), and which sphere; −1 if none.</summary>
        public int Hit(Vector3d origin, Vector3d direction, out double s) =>
            _scene.Trace(origin, direction, 0, out s, out _, out _, out _, out var id) ? id - 1 : -1;

        /// <summary>The world-space ray (not unit) through continuous pixel (u, v) whose camera-axis depth is the ray parameter.</summary>
        public static Vector3d Ray(Matrix4x4d cameraToWorld, CameraIntrinsics k, double u, double v)
        {
            // OpenCV direction ((u − cx)/fx, (v − cy)/fy, 1) in OpenGL axes is (x, −y, −z).
            var x = (u - k.Cx) / k.FlX;
            var y = (v - k.Cy) / k.FlY;
            return cameraToWorld.Column(0) * x - cameraToWorld.Column(1) * y - cameraToWorld.Column(2);
        }

        /// <summary>Camera-axis depth of the nearest surface through pixel (u, v), or 0.</summary>
        public double DepthAt(Matrix4x4d cameraToWorld, CameraIntrinsics k, double u, double v) =>
            Hit(cameraToWorld.Translation, Ray(cameraToWorld, k, u, v), out var s) >= 0 ? s : 0;

        public void Render(Matrix4x4d cameraToWorld, CameraIntrinsics k, out ushort[] depth, out byte[] mask, out byte[] rgba)
        {
            int w = k.Width, h = k.Height;
            depth = new ushort[w * h];
            mask = new byte[w * h];
            rgba = new byte[w * h * 4];
            var which = new int[w * h];
            var origin = cameraToWorld.Translation;
            for (var j = 0; j < h; j++)
                for (var i = 0; i < w; i++)
                {
                    var at = j * w + i;
                    which[at] = Hit(origin, Ray(cameraToWorld, k, i + 0.5, j + 0.5), out var s);
                    if (which[at] < 0) continue;
                    depth[at] = (ushort)Math.Min(65535, Math.Floor(s * 1000 + 0.5));
                    var sphere = Spheres[which[at]];
                    rgba[4 * at] = sphere.Red; rgba[4 * at + 1] = sphere.Green; rgba[4 * at + 2] = sphere.Blue; rgba[4 * at + 3] = 255;
                }
            for (var j = 0; j < h; j++)
                for (var i = 0; i < w; i++)
                {
                    var at = j * w + i;
                    var covered = which[at] >= 0;
                    var edge = (i > 0 && (which[at - 1] >= 0) != covered) || (i + 1 < w && (which[at + 1] >= 0) != covered) ||
                               (j > 0 && (which[at - w] >= 0) != covered) || (j + 1 < h && (which[at + w] >= 0) != covered);
                    if (!edge) { mask[at] = covered ? (byte)255 : (byte)0; continue; }
                    var hits = 0;
                    for (var sub = 0; sub < 4; sub++)
                        if (Hit(origin, Ray(cameraToWorld, k, i + 0.25 + 0.5 * (sub & 1), j + 0.25 + 0.5 * (sub >> 1)), out _) >= 0) hits++;
                    mask[at] = (byte)Math.Round(255.0 * hits / 4);
                }
        }

        /// <summary><paramref name="count"/> points uniform by area over all spheres (Archimedes: z uniform), exact outward normals.</summary>
        public List<CloudPoint> Sample(int count, int seed)
        {
            var random = new Random(seed);
            var areas = new double[Spheres.Length];
            double total = 0;
            for (var i = 0; i < Spheres.Length; i++) total += areas[i] = 4 * Math.PI * Spheres[i].Radius * Spheres[i].Radius;
            var points = new List<CloudPoint>(count);
            for (var n = 0; n < count; n++)
            {
                var pick = random.NextDouble() * total;
                var i = 0;
                while (i < Spheres.Length - 1 && pick >= areas[i]) pick -= areas[i++];
                var z = 2 * random.NextDouble() - 1;
                var phi = 2 * Math.PI * random.NextDouble();
                var rho = Math.Sqrt(Math.Max(0, 1 - z * z));
                var normal = new Vector3d(rho * Math.Cos(phi), rho * Math.Sin(phi), z);
                var sphere = Spheres[i];
                // Float32 as the PLY stores it, so the test's points are the file's points.
                var p = sphere.Centre + normal * sphere.Radius;
                points.Add(new CloudPoint(new Vector3d((float)p.X, (float)p.Y, (float)p.Z), new Vector3d((float)normal.X, (float)normal.Y, (float)normal.Z),
                    sphere.Red, sphere.Green, sphere.Blue));
            }
            return points;
        }

        /// <summary>An OpenGL camera-to-world matrix at <paramref name="eye"/> looking at <paramref name="target"/>, +Z up.</summary>
        public static Matrix4x4d LookAt(Vector3d eye, Vector3d target)
        {
            var forward = (target - eye).Normalized();
            var right = Vector3d.Cross(forward, Vector3d.UnitZ).Normalized();
            var up = Vector3d.Cross(right, forward);
            return Matrix4x4d.FromColumns(right, up, -forward, eye);
        }

        /// <summary>
        /// Writes a Blender-format dataset into <paramref name="root"/>: every view as <c>&lt;split&gt;/r_&lt;i&gt;</c> with
        /// depth and mask (named by <c>depth_path</c> / <c>mask_path</c>), all three split files, <paramref name="points"/> as points3d.ply and its record.
        /// <paramref name="alterMask"/> may change a view's mask before it is written (view index, mask).
        /// </summary>
        public void WriteDataset(string root, IReadOnlyList<(string Split, Matrix4x4d CameraToWorld)> views, CameraIntrinsics k,
            IReadOnlyList<CloudPoint> points, bool withDepth = true, Action<int, byte[]> alterMask = null)
        {
            Directory.CreateDirectory(root);
            var splits = new Dictionary<string, JArray> { ["train"] = new JArray(), ["val"] = new JArray(), ["test"] = new JArray() };
            var counters = new Dictionary<string, int> { ["train"] = 0, ["val"] = 0, ["test"] = 0 };
            for (var v = 0; v < views.Count; v++)
            {
                var (split, c2w) = views[v];
                var name = split + "/r_" + counters[split]++.ToString(CultureInfo.InvariantCulture);
                Directory.CreateDirectory(Path.Combine(root, split));
                Render(c2w, k, out var depth, out var mask, out var rgba);
                alterMask?.Invoke(v, mask);
                File.WriteAllBytes(Path.Combine(root, name + ".png"), PngWriter.Encode(rgba, k.Width, k.Height, PngPixelFormat.Rgba8));
                if (withDepth)
                {
                    File.WriteAllBytes(Path.Combine(root, name + "_depth_0000.png"), PngWriter.EncodeGray16(depth, k.Width, k.Height));
                    File.WriteAllBytes(Path.Combine(root, name + "_mask_0000.png"), PngWriter.Encode(mask, k.Width, k.Height, PngPixelFormat.Gray8));
                }
                var matrix = new JArray();
                for (var r = 0; r < 4; r++)
                {
                    var row = new JArray();
                    for (var c = 0; c < 4; c++) row.Add(c2w[r, c]);
                    matrix.Add(row);
                }
                var frame = new JObject { ["file_path"] = "./" + name, ["transform_matrix"] = matrix };
                if (withDepth)
                {
                    // Named by key, as the plugin writes them: every reader takes a frame's files from its keys only.
                    frame["depth_path"] = "./" + name + "_depth_0000.png";
                    frame["mask_path"] = "./" + name + "_mask_0000.png";
                }
                splits[split].Add(frame);
            }
            foreach (var split in splits)
                File.WriteAllText(Path.Combine(root, "transforms_" + split.Key + ".json"), new JObject
                {
                    ["camera_angle_x"] = k.CameraAngleX,
                    ["cx"] = k.Cx,
                    ["cy"] = k.Cy,
                    ["frames"] = split.Value,
                }.ToString());
            var config = new JObject { ["generator"] = PluginInfo.Name };
            if (points != null)
            {
                var ply = Path.Combine(root, PointCloudOwnership.FileName);
                PlyWriter.Write(ply, points);
                config[PointCloudRecord.Key] = PointCloudRecord.Of(ply, PointCloudOwnership.FileName, points.Count).ToJson();
            }
            File.WriteAllText(Path.Combine(root, DatasetLayout.ConfigFileName), config.ToString());
        }
    }
}
