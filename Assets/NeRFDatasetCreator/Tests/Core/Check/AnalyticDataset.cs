using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Writes a real dataset folder through the capture's own Core path — <see cref="DatasetRun"/>'s plan, transforms
    /// and dataset_config.json, <see cref="ViewFileWriter"/> (difference matting, mask, 16-bit depth, normals, PNG),
    /// <c>points3d.ply</c> with its record — from readbacks ray-traced per sample through NeRF's own ray formula
    /// (<see cref="NerfRays"/>) from each view's written <c>transform_matrix</c> and <c>camera_angle_x</c>: exactly what a
    /// correct capture of <see cref="AnalyticScene"/> must give.
    /// </summary>
    static class AnalyticDataset
    {
        public sealed class Options
        {
            public int Width = 96, Height = 72, Supersampling = 2;
            public int Train = 10, Val = 3, Test = 3;
            public bool Normalised { get; set; }

            /// <summary>More than 1: a multi-view dynamic capture with moving content.</summary>
            public int TimeSteps { get; set; }

            /// <summary>With <see cref="TimeSteps"/>: a monocular capture instead (one train view per step; set Train to the steps).</summary>
            public bool Monocular { get; set; }
            public int PointCloud = 2000;

            /// <summary>Depth and normals rendered at the output size (the capture's default, CaptureOptions.DepthAndNormalAtOutputSize), else at the supersampled size.</summary>
            public bool DataAtOutputSize = true;

            /// <summary>A planted fault: the depth pass holds the distance along each pixel's ray instead of z.</summary>
            public bool DepthAlongRay { get; set; }

            /// <summary>The geometry pack's meshes (Unity world) at a normalised time (<see cref="AnalyticSceneMeshes.At"/>); null: no pack.</summary>
            public Func<double, IReadOnlyList<SurfaceMesh>> MeshesAt { get; set; }

            /// <summary><c>"geometryPack": "everyStep"</c>.</summary>
            public bool GeometryPackEveryStep { get; set; }

            /// <summary>A shard of the capture, written to <see cref="Folder"/> (relative to the project).</summary>
            public ShardSpec Shard { get; set; }

            public string Folder { get; set; }
        }

        public static readonly Vector3d Centre = new Vector3d(1, 2, 3);
        const double Radius = 1.2;

        /// <summary>Renders the dataset into <paramref name="project"/>/NeRFDatasets/<paramref name="name"/> and returns its folder.</summary>
        public static string Write(string project, string name, Options options)
        {
            var settings = new DatasetSettings { Name = name, Width = options.Width, Height = options.Height, Supersampling = options.Supersampling, Distance = options.Normalised ? 8 : 4 };
            if (options.Normalised) settings.Normalisation = NormalisationMode.NerfSyntheticScale; // s = 4 / 8
            foreach (var (split, count) in new[] { (settings.Train, options.Train), (settings.Val, options.Val), (settings.Test, options.Test) })
            {
                split.Count = count;
                split.Depth = ExtraOutput.Png;
                split.Normal = ExtraOutput.Png;
                split.Mask = true;
            }
            if (options.TimeSteps > 1)
            {
                settings.Time.Mode = options.Monocular ? TimeMode.Monocular : TimeMode.MultiView;
                settings.Time.Steps = options.TimeSteps;
                settings.Time.StartSeconds = 0;
                settings.Time.EndSeconds = 1;
            }
            settings.GeometryPackEveryStep = options.GeometryPackEveryStep;
            var run = DatasetRun.Prepare(settings, new PlanTarget(Centre, Radius, options.TimeSteps > 1 ? 1 : 0), project, options.Shard, options.Folder);
            Assert.That(run.Problems, Is.Empty, "the test dataset's settings");
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, null);
            var scenes = new Dictionary<double, AnalyticScene>();
            foreach (var view in run.Plan.Views)
            {
                var time = view.Time?.Normalised ?? 0;
                if (!scenes.TryGetValue(time, out var scene)) scenes[time] = scene = AnalyticScene.Layout(run.Plan.Normalisation, Centre, time);
                var frame = Render(scene, view.TransformMatrix, run.Plan.Intrinsics, options, run.Plan.Normalisation.Scale, options.Supersampling);
                var data = options.DataAtOutputSize && options.Supersampling > 1 ? Render(scene, view.TransformMatrix, run.Plan.Intrinsics, options, run.Plan.Normalisation.Scale, 1) : frame;
                writer.Write(view, frame, data);
            }
            var cloud = options.PointCloud > 0 ? AnalyticScene.Layout(run.Plan.Normalisation, Centre).Surface(options.PointCloud) : null;
            var meshesAt = options.MeshesAt;
            run.Finish(session, new Provenance(new DateTime(2026, 11, 27, 10, 0, 0, DateTimeKind.Utc)), cloud, meshesAt?.Invoke(0),
                meshesAt == null || run.Plan.Time == null ? (Func<int, IReadOnlyList<SurfaceMesh>>)null : k => meshesAt(run.Plan.Time.NormalisedOf(k)));
            return run.DatasetFolder;
        }

        /// <summary>The readbacks of one view: colour over black and white (halves), mask, eye z-depth (metric) and output-world normals, rows bottom first.</summary>
        static RawFrame Render(AnalyticScene scene, Matrix4x4d c2w, CameraIntrinsics intrinsics, Options options, double scale, int k)
        {
            int w = intrinsics.Width * k, h = intrinsics.Height * k;
            var frame = new RawFrame(w, h, k)
            {
                ColorOverBlack = new ushort[w * h * 4], ColorOverWhite = new ushort[w * h * 4], Mask = new byte[w * h], MaskBytesPerPixel = 1,
                Depth = new float[w * h], Normals = new float[w * h * 4], NormalsInUnityWorld = false,
            };
            var rows = c2w.ToRows();
            var light = new Vector3d(0.3, -0.5, 0.8).Normalized();
            for (var ys = 0; ys < h; ys++)
                for (var xs = 0; xs < w; xs++)
                {
                    // The sample's position in output pixels (continuous, top-left origin), and NeRF's ray through it.
                    double i = (xs + 0.5) / k, j = (ys + 0.5) / k;
                    NerfRays.Ray(rows, intrinsics.CameraAngleX, intrinsics.Width, intrinsics.Height, i, j, out var origin, out var direction);
                    var o = new Vector3d(origin[0], origin[1], origin[2]);
                    var d = new Vector3d(direction[0], direction[1], direction[2]);
                    var p = ((h - 1 - ys) * w + xs); // readbacks are bottom row first
                    double[] black = { 0, 0, 0 }, white = { 1, 1, 1 };
                    Composite(scene, o, d, 0, light, black, white, out var first, out var normal, 3);
                    for (var c = 0; c < 3; c++)
                    {
                        frame.ColorOverBlack[p * 4 + c] = Half(black[c]);
                        frame.ColorOverWhite[p * 4 + c] = Half(white[c]);
                    }
                    if (double.IsInfinity(first)) continue;
                    frame.Mask[p] = 255;
                    // The ray's camera-space z component is −1, so its parameter is the z-depth (output units).
                    var depth = options.DepthAlongRay ? first * d.Length : first;
                    frame.Depth[p] = (float)(depth / scale);
                    frame.Normals[p * 4] = (float)normal.X;
                    frame.Normals[p * 4 + 1] = (float)normal.Y;
                    frame.Normals[p * 4 + 2] = (float)normal.Z;
                }
            return frame;
        }

        /// <summary>
        /// Blends the surfaces along the ray front to back over black and over white, as the GPU does (out = F + T·B):
        /// Lambert-shaded colour, glass at its alpha. Returns the first surface's t and normal (depth and normals are of it).
        /// </summary>
        static void Composite(AnalyticScene scene, Vector3d o, Vector3d d, double after, Vector3d light, double[] black, double[] white,
            out double first, out Vector3d firstNormal, int depthLeft)
        {
            first = double.PositiveInfinity;
            firstNormal = Vector3d.Zero;
            if (depthLeft == 0 || !scene.Trace(o, d, after, out var t, out var normal, out var colour, out var alpha)) return;
            first = t;
            firstNormal = normal;
            var shade = 0.35 + 0.65 * Math.Max(0, Vector3d.Dot(normal, light));
            double[] behindBlack = { 0, 0, 0 }, behindWhite = { 1, 1, 1 };
            if (alpha < 1) Composite(scene, o, d, t + 1e-9, light, behindBlack, behindWhite, out _, out _, depthLeft - 1);
            for (var c = 0; c < 3; c++)
            {
                var surface = colour[c] * shade;
                black[c] = alpha * surface + (1 - alpha) * behindBlack[c];
                white[c] = alpha * surface + (1 - alpha) * behindWhite[c];
            }
        }

        /// <summary>The nearest half float to a value in [0, 1] (the colour renders' format).</summary>
        public static ushort Half(double value)
        {
            if (!(value > 0)) return 0;
            if (value >= 1) return 0x3C00;
            var exponent = (int)Math.Floor(Math.Log(value, 2));
            if (exponent < -14) return (ushort)Math.Round(value / Math.Pow(2, -24)); // subnormal
            var mantissa = (int)Math.Round((value / Math.Pow(2, exponent) - 1) * 1024);
            if (mantissa == 1024) { mantissa = 0; exponent++; }
            return (ushort)(((exponent + 15) << 10) | mantissa);
        }
    }
}
