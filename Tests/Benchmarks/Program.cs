using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Threading;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Prints figures; asserts nothing. The same sources build for .NET (this project) and for Mono, the runtime
    /// Unity's editor runs (Tests/Benchmarks/run-all builds both, runs both and prints them side by side with
    /// Pillow's PNG encoder as an anchor).
    /// Options: --only post|matting|png|view|plan|tracks|eval|check|labels|exposure|lens|blur|flow (one section; check, exposure, lens, blur and flow only when named; check renders a 300-view dataset once), --dump-eval DIR (evaluation's image pair and clouds for evaluate_anchor.py), --dump-flow DIR (the flow mesh and rays for flow_anchor.c), --tsv FILE (figures as "key TAB value" lines for run-all),
    /// --dump DIR (the raw images the PNG figures use, for the Pillow anchor), --batches N.
    /// </summary>
    static class Program
    {
        const int OutputSize = 800;
        const int Supersampling = 2;

        static readonly List<KeyValuePair<string, double>> Figures = new List<KeyValuePair<string, double>>();
        static int batches = 3;

        static void Main(string[] args)
        {
            if (Array.IndexOf(args, "--check-folder") >= 0)
            {
                Console.WriteLine(CheckBenchmark.Folder); // for run-all's Pillow decoding of the same files
                return;
            }
            string only = Option(args, "--only"), tsv = Option(args, "--tsv"), dump = Option(args, "--dump");
            if (Option(args, "--batches") != null) batches = int.Parse(Option(args, "--batches"), System.Globalization.CultureInfo.InvariantCulture);
            Console.WriteLine($"NeRF Dataset Creator benchmarks — {Environment.ProcessorCount} logical cores, {Runtime}, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}");
            Console.WriteLine($"Times are CPU time of this process per run, the cheapest of {batches} interleaved batches of ≥ {BatchCpuMs} ms; single thread unless said otherwise.");
            Console.WriteLine();

            if (only == null || only == "post") PostProcessing();
            if (only == null || only == "matting") MattingBenchmark.Run();
            if (dump != null) Dump(Images.Make(), dump);
            if (only == null || only == "png") Png();
            if (only == null || only == "view") WholeView();
            if (only == null || only == "plan") TransformsBenchmark.Run(Record);
            if (only == null || only == "tracks") TracksBenchmark.Run(Record, batches);
            if (Option(args, "--dump-eval") != null) EvaluationBenchmark.Dump(Option(args, "--dump-eval"));
            if (only == null || only == "eval") EvaluationBenchmark.Run(Record, batches);
            if (only == "check") CheckBenchmark.Run(Record, steps => Interleaved(false, steps));
            if (only == "exposure") ExposureBenchmark.Run(Record, steps => Interleaved(true, steps));
            if (only == "lens") LensBenchmark.Run(Record, steps => Interleaved(true, steps));
            if (only == null || only == "labels") LabelsBenchmark.Run(Record, steps => Interleaved(steps));
            if (only == "blur") MotionBlurBenchmark.Run(Record, steps => Interleaved(steps));
            if (only == "flow" || Option(args, "--dump-flow") != null) FlowBenchmark.Run(Record, only == "flow" ? batches : 0, Option(args, "--dump-flow"));

            if (tsv != null)
                using (var file = new StreamWriter(tsv))
                    foreach (var figure in Figures) file.WriteLine(figure.Key + "\t" + figure.Value.ToString("R", System.Globalization.CultureInfo.InvariantCulture));
        }

        static string Runtime => Type.GetType("Mono.Runtime") != null
            ? "Mono (" + System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription + ")"
            : System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription;

        static string Option(string[] args, string name)
        {
            int at = Array.IndexOf(args, name);
            return at >= 0 && at + 1 < args.Length ? args[at + 1] : null;
        }

        static void Record(string key, double value) => Figures.Add(new KeyValuePair<string, double>(key, value));

        /// <summary>Post-processing in the capture's own layout (R8 mask; depth and normals rendered at the output size).</summary>
        static void PostProcessing()
        {
            var (colour, data) = SyntheticFrame.CaptureLayout(OutputSize, Supersampling);
            int pixels = OutputSize * OutputSize;
            var rgba = new byte[pixels * 4];
            var mask = new byte[pixels];
            var depth = new ushort[pixels];
            var normals = new byte[pixels * 3];
            var blackCopy = new ushort[colour.ColorOverBlack.Length];
            var whiteCopy = new ushort[colour.ColorOverWhite.Length];
            var maskCopy = new byte[colour.Mask.Length];
            var depthCopy = new float[data.Depth.Length];
            var normalCopy = new float[data.Normals.Length];
            long inputBytes = 2L * blackCopy.Length + 2L * whiteCopy.Length + colour.Mask.Length + 4L * data.Depth.Length + 4L * data.Normals.Length;
            Console.WriteLine($"Post-processing one {OutputSize}×{OutputSize} view in the capture's layout: two {colour.Width}×{colour.Height} RGBA half renders (over black and white) + R8 mask, " +
                              $"{OutputSize}×{OutputSize} depth and RGBA float Unity-world normals ({inputBytes / 1e6:F1} MB); ms:");
            var t = Interleaved(
                ("plain copy of the same input bytes", () =>
                {
                    Buffer.BlockCopy(colour.ColorOverBlack, 0, blackCopy, 0, blackCopy.Length * 2);
                    Buffer.BlockCopy(colour.ColorOverWhite, 0, whiteCopy, 0, whiteCopy.Length * 2);
                    Buffer.BlockCopy(colour.Mask, 0, maskCopy, 0, maskCopy.Length);
                    Buffer.BlockCopy(data.Depth, 0, depthCopy, 0, depthCopy.Length * 4);
                    Buffer.BlockCopy(data.Normals, 0, normalCopy, 0, normalCopy.Length * 4);
                }),
                ("colour + alpha by difference matting", () => DifferenceMatting.Resolve(colour, rgba)),
                ("mask image", () => MaskEncoding.Encode(colour, mask)),
                ("depth, 16-bit millimetres", () => DepthEncoding.ToMillimetres(data, depth)),
                ("normals, relabelled to the output world, 8-bit RGB", () => NormalEncoding.Encode(data, normals)),
                ("all of the above", () =>
                {
                    DifferenceMatting.Resolve(colour, rgba);
                    MaskEncoding.Encode(colour, mask);
                    DepthEncoding.ToMillimetres(data, depth);
                    NormalEncoding.Encode(data, normals);
                }));
            Console.WriteLine($"  ratio all / copy: {t[5] / t[0]:F2}×");
            Record("post.copy.ms", t[0]);
            Record("post.colour.ms", t[1]);
            Record("post.all.ms", t[5]);
            Record("post.ratio", t[5] / t[0]);
            Console.WriteLine();
        }

        /// <summary>The post-processed images of one view, as the PNG figures and the Pillow anchor use them.</summary>
        sealed class Images
        {
            public byte[] Rgba, RgbaClean, Mask, Normals;
            public ushort[] Depth;

            public static Images Make()
            {
                var images = new Images();
                int pixels = OutputSize * OutputSize;
                var (colour, data) = SyntheticFrame.CaptureLayout(OutputSize, Supersampling);
                images.Rgba = new byte[pixels * 4];
                images.Mask = new byte[pixels];
                DifferenceMatting.Resolve(colour, images.Rgba);
                MaskEncoding.Encode(colour, images.Mask);
                images.RgbaClean = new byte[pixels * 4];
                DifferenceMatting.Resolve(SyntheticFrame.CaptureLayout(OutputSize, Supersampling, noise: 0).Colour, images.RgbaClean);
                images.Depth = new ushort[pixels];
                DepthEncoding.ToMillimetres(data, images.Depth);
                images.Normals = new byte[pixels * 3];
                NormalEncoding.Encode(data, images.Normals);
                return images;
            }
        }

        static void Png()
        {
            var images = Images.Make();
            Console.WriteLine($"PNG encode of {OutputSize}×{OutputSize} images; size in KB, ms, MB/s of raw pixels:");
            Console.WriteLine("  image                     encoder                          KB      ms    MB/s");
            var encoders = new (string Key, string Name, PngCompression Compression, PngFilter Filter)[]
            {
                ("lz77", "Lz77 (greedy, one candidate)", PngCompression.Lz77, PngFilter.Adaptive),
                ("huffman", "Huffman (default)", PngCompression.Huffman, PngFilter.Adaptive),
                ("zlib6", "DeflateStream Optimal, Sub (old)", PngCompression.Optimal, PngFilter.Sub),
                ("zlib1", "DeflateStream Fastest, Sub", PngCompression.Fastest, PngFilter.Sub),
            };
            var inputs = new (string Key, string Name, long Bytes, Func<PngCompression, PngFilter, byte[]> Encode)[]
            {
                ("rgba", "RGBA render with grain", images.Rgba.Length, (c, f) => PngWriter.Encode(images.Rgba, OutputSize, OutputSize, PngPixelFormat.Rgba8, c, f)),
                ("rgba-clean", "RGBA render without grain", images.RgbaClean.Length, (c, f) => PngWriter.Encode(images.RgbaClean, OutputSize, OutputSize, PngPixelFormat.Rgba8, c, f)),
                ("mask", "mask (gray 8)", images.Mask.Length, (c, f) => PngWriter.Encode(images.Mask, OutputSize, OutputSize, PngPixelFormat.Gray8, c, f)),
                ("depth", "depth (gray 16)", images.Depth.Length * 2L, (c, f) => PngWriter.EncodeGray16(images.Depth, OutputSize, OutputSize, c, f)),
                ("normal", "normals (RGB 8)", images.Normals.Length, (c, f) => PngWriter.Encode(images.Normals, OutputSize, OutputSize, PngPixelFormat.Rgb8, c, f)),
            };
            var steps = new List<(string Name, Action Run)>();
            foreach (var input in inputs)
                foreach (var encoder in encoders)
                {
                    var i = input;
                    var e = encoder;
                    steps.Add((i.Key + " " + e.Key, () => i.Encode(e.Compression, e.Filter)));
                }
            var times = Interleaved(false, steps.ToArray());
            int n = 0;
            foreach (var input in inputs)
                foreach (var encoder in encoders)
                {
                    double ms = times[n++];
                    int size = input.Encode(encoder.Compression, encoder.Filter).Length;
                    double mbs = input.Bytes / 1e6 / (ms / 1000);
                    Console.WriteLine($"  {input.Name,-25} {encoder.Name,-32} {size / 1024.0,6:F1} {ms,7:F2} {mbs,7:F0}");
                    Record($"png.{input.Key}.{encoder.Key}.ms", ms);
                    Record($"png.{input.Key}.{encoder.Key}.kb", size / 1024.0);
                    Record($"png.{input.Key}.{encoder.Key}.mbs", mbs);
                }
            Console.WriteLine();
        }

        static void Dump(Images images, string folder)
        {
            Directory.CreateDirectory(folder);
            File.WriteAllBytes(Path.Combine(folder, "rgba-800x800.raw"), images.Rgba);
            File.WriteAllBytes(Path.Combine(folder, "rgba-clean-800x800.raw"), images.RgbaClean);
            File.WriteAllBytes(Path.Combine(folder, "mask-800x800.raw"), images.Mask);
            File.WriteAllBytes(Path.Combine(folder, "normal-800x800.raw"), images.Normals);
            var bigEndian = new byte[images.Depth.Length * 2];
            for (int i = 0; i < images.Depth.Length; i++)
            {
                bigEndian[2 * i] = (byte)(images.Depth[i] >> 8);
                bigEndian[2 * i + 1] = (byte)images.Depth[i];
            }
            File.WriteAllBytes(Path.Combine(folder, "depth16be-800x800.raw"), bigEndian);
            Console.WriteLine($"Raw images written to {folder}");
        }

        /// <summary>
        /// The worker's whole job for one view, as the capture runs it: ViewFileWriter.Write (post-processing, the
        /// colour, mask, depth and normal PNGs, file writes) into a temp folder, with 1 and with N threads.
        /// </summary>
        static void WholeView()
        {
            var settings = new DatasetSettings { Name = "bench", Width = OutputSize, Height = OutputSize };
            foreach (var split in DatasetSplits.All)
            {
                var s = settings.Split(split);
                s.Count = 8;
                s.Mask = true;
                s.Depth = ExtraOutput.Png;
                s.Normal = ExtraOutput.Png;
            }
            var plan = CapturePlan.Build(settings, PlanTarget.AtOrigin);
            var (colour, data) = SyntheticFrame.CaptureLayout(OutputSize, Supersampling);
            var root = Path.Combine(Path.GetTempPath(), "nerf-bench-" + Guid.NewGuid().ToString("N"));
            var session = DatasetWriteSession.Begin(root, OverwritePolicy.Never);
            try
            {
                var writer = new ViewFileWriter(plan, session, null);
                int workers = Environment.ProcessorCount;
                Console.WriteLine($"Whole view: ViewFileWriter.Write of one {OutputSize}×{OutputSize} view (colour, mask, 16-bit depth, normal PNGs, written to disk):");
                writer.Write(plan.Views[0], colour, data);
                int view = 0;
                double best = Interleaved(false, ("view", () => writer.Write(plan.Views[view++ % plan.Views.Count], colour, data)))[0];
                double share = writer.PngEncodeSeconds / writer.WriteSeconds;
                Console.WriteLine($"  1 thread:  {best,6:F1} ms CPU per view = {1000 / best,5:F1} views/s per core; PNG encoding {100 * share:F0} % of the writer's time");
                Record("view.1.ms", best);
                Record("view.1.vps", 1000 / best);
                Record("view.png-share", share);

                double bestRate = 0;
                for (int round = 0; round < 3 * batches; round++)
                {
                    var threads = new Thread[workers];
                    int perThread = 4;
                    var watch = Stopwatch.StartNew();
                    for (int t = 0; t < workers; t++)
                    {
                        int first = t * perThread;
                        threads[t] = new Thread(() =>
                        {
                            for (int v = 0; v < perThread; v++) writer.Write(plan.Views[(first + v) % plan.Views.Count], colour, data);
                        });
                        threads[t].Start();
                    }
                    foreach (var thread in threads) thread.Join();
                    bestRate = Math.Max(bestRate, workers * perThread / watch.Elapsed.TotalSeconds);
                }
                Console.WriteLine($"  {workers} threads: {bestRate,5:F1} views/s, wall clock, best of {3 * batches} rounds ({bestRate / (1000 / best):F2}× one thread's CPU-time rate; a shared machine lowers it)");
                Record("view.n.vps", bestRate);
                Record("view.n.workers", workers);
            }
            finally
            {
                if (Directory.Exists(session.WorkingFolder)) Directory.Delete(session.WorkingFolder, true);
                if (Directory.Exists(root)) Directory.Delete(root, true);
            }
            Console.WriteLine();
        }

        static double[] Interleaved(params (string Name, Action Run)[] steps) => Interleaved(true, steps);

        /// <summary>
        /// Each step's cost in ms of CPU time per run. The machine this was written on is shared (2 cores, often
        /// dozens of runnable processes), so wall time mostly measures the queue; the process's CPU time excludes
        /// the time others held the core. It is read with 10 ms resolution, so each step runs in batches of at
        /// least <see cref="BatchCpuMs"/>; batches of all steps take turns (load hits them alike) and the cheapest
        /// of <see cref="batches"/> batches counts. Includes the runtime's own threads (JIT, GC), as a user pays them.
        /// </summary>
        static double[] Interleaved(bool print, params (string Name, Action Run)[] steps)
        {
            var best = new double[steps.Length];
            for (int i = 0; i < steps.Length; i++)
            {
                steps[i].Run();
                steps[i].Run();
                best[i] = double.MaxValue;
            }
            var process = Process.GetCurrentProcess();
            for (int batch = 0; batch < batches; batch++)
                for (int i = 0; i < steps.Length; i++)
                {
                    process.Refresh();
                    var start = process.TotalProcessorTime;
                    int runs = 0;
                    double used;
                    do
                    {
                        steps[i].Run();
                        runs++;
                        process.Refresh();
                        used = (process.TotalProcessorTime - start).TotalMilliseconds;
                    } while (used < BatchCpuMs);
                    best[i] = Math.Min(best[i], used / runs);
                }
            if (print)
                for (int i = 0; i < steps.Length; i++) Console.WriteLine($"  {steps[i].Name,-52} {best[i],7:F2}");
            return best;
        }

        const double BatchCpuMs = 250;
    }
}
