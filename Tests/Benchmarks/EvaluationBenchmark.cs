using System;
using System.Diagnostics;
using System.IO;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// <c>--only eval</c>: 3DGS SSIM of one 800×800 RGB pair (single thread), the whole evaluation of 200 such views
    /// (<see cref="RenderEvaluator"/>: decode, PSNR, masked PSNR, SSIM, error map and thumbnails, report; all cores),
    /// and Chamfer / F-score of 1 M against 1 M surface points (k-d trees, single thread). <c>--dump-eval DIR</c> writes
    /// the same image pair and clouds as raw float32 for evaluate_anchor.py (scikit-image, SciPy cKDTree).
    /// </summary>
    static class EvaluationBenchmark
    {
        const int Size = 800;
        const int Views = 200;
        const int Points = 1_000_000;

        /// <summary>A smooth shaded disc with texture, and a render of it with a small shift and noise: SSIM well below 1.</summary>
        public static (float[] truth, float[] render) Pair()
        {
            var truth = new float[Size * Size * 3];
            var render = new float[Size * Size * 3];
            var random = new Random(3);
            for (var y = 0; y < Size; y++)
                for (var x = 0; x < Size; x++)
                {
                    double dx = x - 400, dy = y - 400;
                    var inside = dx * dx + dy * dy < 300 * 300;
                    for (var c = 0; c < 3; c++)
                    {
                        var i = (y * Size + x) * 3 + c;
                        var v = inside ? 0.5 + 0.3 * Math.Sin(0.05 * x + c) * Math.Cos(0.07 * y) : 1.0;
                        truth[i] = (float)v;
                        var shifted = inside ? 0.5 + 0.3 * Math.Sin(0.05 * (x + 0.7) + c) * Math.Cos(0.07 * y) : 1.0;
                        render[i] = (float)Math.Max(0, Math.Min(1, shifted + (random.NextDouble() - 0.5) * 0.04));
                    }
                }
            return (truth, render);
        }

        public static (float[] recon, float[] truth) Clouds()
        {
            var truth = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { Sphere(1.0) }, Points, 1));
            var recon = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { Sphere(1.01) }, Points, 2));
            return (recon, truth);
        }

        static SurfaceMesh Sphere(double radius)
        {
            const int rings = 128, segments = 256;
            var vertices = new System.Collections.Generic.List<Vector3d>();
            var triangles = new System.Collections.Generic.List<int>();
            for (var r = 0; r <= rings; r++)
                for (var s = 0; s < segments; s++)
                {
                    double theta = Math.PI * r / rings, phi = 2 * Math.PI * s / segments;
                    vertices.Add(new Vector3d(Math.Sin(theta) * Math.Cos(phi), Math.Sin(theta) * Math.Sin(phi), Math.Cos(theta)) * radius);
                }
            for (var r = 0; r < rings; r++)
                for (var s = 0; s < segments; s++)
                {
                    int a = r * segments + s, b = r * segments + (s + 1) % segments, c = (r + 1) * segments + s, d = (r + 1) * segments + (s + 1) % segments;
                    triangles.AddRange(new[] { a, c, b, b, c, d });
                }
            return new SurfaceMesh(vertices, triangles);
        }

        public static void Dump(string folder)
        {
            Directory.CreateDirectory(folder);
            var (truth, render) = Pair();
            WriteFloats(Path.Combine(folder, "ssim-truth-800x800x3.f32"), truth);
            WriteFloats(Path.Combine(folder, "ssim-render-800x800x3.f32"), render);
            var (recon, points) = Clouds();
            WriteFloats(Path.Combine(folder, "chamfer-recon.f32"), recon);
            WriteFloats(Path.Combine(folder, "chamfer-truth.f32"), points);
        }

        static void WriteFloats(string path, float[] values)
        {
            var bytes = new byte[values.Length * 4];
            Buffer.BlockCopy(values, 0, bytes, 0, bytes.Length);
            File.WriteAllBytes(path, bytes);
        }

        static double CpuMs(Action run, int repeats, out double wallMs)
        {
            var best = double.MaxValue;
            wallMs = double.MaxValue;
            var process = Process.GetCurrentProcess();
            for (var i = 0; i < repeats; i++)
            {
                process.Refresh();
                var start = process.TotalProcessorTime;
                var watch = Stopwatch.StartNew();
                run();
                wallMs = Math.Min(wallMs, watch.Elapsed.TotalMilliseconds);
                process.Refresh();
                best = Math.Min(best, (process.TotalProcessorTime - start).TotalMilliseconds);
            }
            return best;
        }

        public static void Run(Action<string, double> record, int batches)
        {
            Console.WriteLine("Evaluation (nerf-dataset evaluate): ms of process CPU time, the cheapest of " + batches + " runs unless said otherwise:");
            var (truth, render) = Pair();
            double ssim = 0;
            var ssimMs = CpuMs(() => ssim = Ssim.Mean(render, truth, Size, Size, 3), Math.Max(2, batches), out _);
            var psnrMs = CpuMs(() => Psnr.Of(render, truth), Math.Max(2, batches), out _);
            Console.WriteLine($"  SSIM (3DGS: 11×11 Gaussian, zero padding) of an 800×800 RGB pair  {ssimMs,8:F1}   (value {ssim:F6})");
            Console.WriteLine($"  PSNR of the same pair                                             {psnrMs,8:F1}");
            record("eval.ssim.ms", ssimMs);
            record("eval.ssim.value", ssim);
            record("eval.psnr.ms", psnrMs);

            var (recon, points) = Clouds();
            SurfaceDistances distances = null;
            var chamferMs = CpuMs(() => distances = SurfaceDistances.Compute(recon, points, null, 0.015), Math.Max(1, batches / 2), out var chamferWall);
            Console.WriteLine($"  Chamfer + F-score, 1 M vs 1 M points (two k-d trees, both ways)   {chamferMs,8:F0}   (accuracy {distances.Accuracy:F6}, completeness {distances.Completeness:F6}, F {distances.FScore:F4})");
            record("eval.chamfer.ms", chamferMs);
            record("eval.chamfer.value", distances.Chamfer);

            var folder = Path.Combine(Path.GetTempPath(), "nerf-bench-eval-" + Guid.NewGuid().ToString("N"));
            try
            {
                var cpu = WholeEvaluation(folder, truth, render, out var wall, out var psnr);
                Console.WriteLine($"  whole evaluation of {Views} views of 800×800 (decode, PSNR, masked PSNR, SSIM, error map, thumbnails, report), {Environment.ProcessorCount} threads: " +
                                  $"{wall / 1000:F1} s wall, {cpu / 1000:F1} s CPU, {cpu / Views:F0} ms CPU per view (mean PSNR {psnr:F2} dB)");
                record("eval.views.wall.s", wall / 1000);
                record("eval.views.cpu.ms", cpu / Views);
            }
            finally
            {
                if (Directory.Exists(folder)) Directory.Delete(folder, true);
            }
            Console.WriteLine();
        }

        /// <summary>A 200-view dataset whose views are one image pair (decoded afresh for every view, as files), evaluated once.</summary>
        static double WholeEvaluation(string folder, float[] truth, float[] render, out double wallMs, out double meanPsnr)
        {
            var dataset = Path.Combine(folder, "dataset");
            var renders = Path.Combine(folder, "renders");
            Directory.CreateDirectory(Path.Combine(dataset, "test"));
            Directory.CreateDirectory(renders);
            var truthBytes = new byte[Size * Size * 4];
            var mask = new byte[Size * Size];
            var renderBytes = new byte[Size * Size * 3];
            for (var p = 0; p < Size * Size; p++)
            {
                for (var c = 0; c < 3; c++)
                {
                    truthBytes[4 * p + c] = (byte)Math.Round(255 * truth[3 * p + c]);
                    renderBytes[3 * p + c] = (byte)Math.Round(255 * render[3 * p + c]);
                }
                var inside = truth[3 * p] < 1 || truth[3 * p + 1] < 1;
                truthBytes[4 * p + 3] = 255;
                mask[p] = inside ? (byte)255 : (byte)0;
            }
            var truthPng = PngWriter.Encode(truthBytes, Size, Size, PngPixelFormat.Rgba8);
            var maskPng = PngWriter.Encode(mask, Size, Size, PngPixelFormat.Gray8);
            var renderPng = PngWriter.Encode(renderBytes, Size, Size, PngPixelFormat.Rgb8);
            var frames = new System.Text.StringBuilder();
            for (var i = 0; i < Views; i++)
            {
                File.WriteAllBytes(Path.Combine(dataset, "test", "r_" + i + ".png"), truthPng);
                File.WriteAllBytes(Path.Combine(dataset, "test", "r_" + i + "_mask_0000.png"), maskPng);
                File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), renderPng);
                frames.Append(i > 0 ? ",\n" : "").Append("{\"file_path\": \"./test/r_").Append(i).Append("\", \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]], \"mask_path\": \"./test/r_").Append(i).Append("_mask_0000.png\"}");
            }
            File.WriteAllText(Path.Combine(dataset, "transforms_test.json"), "{\"camera_angle_x\": 0.6911112070083618, \"frames\": [\n" + frames + "\n]}");
            EvaluationResult result = null;
            var cpu = CpuMs(() => result = RenderEvaluator.Run(new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders, OutFolder = Path.Combine(folder, "out") }), 1, out wallMs);
            meanPsnr = MetricsJson.Mean(System.Linq.Enumerable.Select(result.Views, v => v.Psnr));
            return cpu;
        }
    }
}
