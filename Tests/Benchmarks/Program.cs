using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Threading.Tasks;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Prints figures; asserts nothing. Usage: dotnet run -c Release --project Tests/Benchmarks [-- --dump DIR]
    /// (--dump writes the raw 800×800 RGBA and 16-bit depth images the PNG figures use, for comparing with libpng).
    /// </summary>
    static class Program
    {
        const int OutputSize = 800;
        const int Supersampling = 2;

        static void Main(string[] args)
        {
            Console.WriteLine($"NeRF Dataset Creator benchmarks — {Environment.ProcessorCount} logical cores, {System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}");
            Console.WriteLine();

            var frame = SyntheticFrame.Sphere(OutputSize, Supersampling);
            var rgba = new byte[OutputSize * OutputSize * 4];
            var mask = new byte[OutputSize * OutputSize];
            var depth = new ushort[OutputSize * OutputSize];
            var normals = new byte[OutputSize * OutputSize * 3];

            PostProcessing(frame, rgba, mask, depth, normals);
            PostProcessingLinearFloat();
            MattingBenchmark.Run();
            Png("RGBA 800×800 textured sphere with grain", rgba, depth: null);
            var clean = new byte[rgba.Length];
            StraightAlpha.Resolve(SyntheticFrame.Sphere(OutputSize, Supersampling, noise: 0), clean);
            Png("RGBA 800×800 textured sphere without grain", clean, depth: null);
            Png("Gray16 800×800 depth (mm)", null, depth);
            TransformsBenchmark.Run();

            int dump = Array.IndexOf(args, "--dump");
            if (dump >= 0 && dump + 1 < args.Length)
            {
                Directory.CreateDirectory(args[dump + 1]);
                File.WriteAllBytes(Path.Combine(args[dump + 1], "rgba-800x800.raw"), rgba);
                File.WriteAllBytes(Path.Combine(args[dump + 1], "rgba-clean-800x800.raw"), clean);
                var bigEndian = new byte[depth.Length * 2];
                for (int i = 0; i < depth.Length; i++) { bigEndian[2 * i] = (byte)(depth[i] >> 8); bigEndian[2 * i + 1] = (byte)depth[i]; }
                File.WriteAllBytes(Path.Combine(args[dump + 1], "depth16be-800x800.raw"), bigEndian);
                Console.WriteLine($"Raw images written to {args[dump + 1]}");
            }
        }

        static void PostProcessing(RawFrame frame, byte[] rgba, byte[] mask, ushort[] depth, byte[] normals)
        {
            Console.WriteLine($"Post-processing one {OutputSize}×{OutputSize} frame from {frame.Width}×{frame.Height} readbacks (k = {Supersampling}), single thread;");
            Console.WriteLine($"all steps interleaved round by round, {Rounds} rounds, fastest and median round in ms:");
            var colourCopy = new byte[frame.ColorSrgb.Length];
            var maskCopy = new byte[frame.Mask.Length];
            var depthCopy = new float[frame.Depth.Length];
            var normalCopy = new float[frame.Normals.Length];
            long inputBytes = frame.ColorSrgb.Length + frame.Mask.Length + 4L * frame.Depth.Length + 4L * frame.Normals.Length;

            var results = Interleaved(
                ("plain copy of the same input bytes (" + (inputBytes / 1e6).ToString("F1") + " MB)", () =>
                {
                    Buffer.BlockCopy(frame.ColorSrgb, 0, colourCopy, 0, colourCopy.Length);
                    Buffer.BlockCopy(frame.Mask, 0, maskCopy, 0, maskCopy.Length);
                    Buffer.BlockCopy(frame.Depth, 0, depthCopy, 0, depthCopy.Length * 4);
                    Buffer.BlockCopy(frame.Normals, 0, normalCopy, 0, normalCopy.Length * 4);
                }),
                ("colour + alpha (sRGB bytes)", () => StraightAlpha.Resolve(frame, rgba)),
                ("colour + alpha + mask image, one pass", () => StraightAlpha.Resolve(frame, rgba, Background.Transparent, mask)),
                ("mask image alone", () => MaskEncoding.Encode(frame, mask)),
                ("depth, 16-bit millimetres", () => DepthEncoding.ToMillimetres(frame, depth)),
                ("normals, 8-bit RGB", () => NormalEncoding.Encode(frame, normals)),
                ("all: colour + alpha + mask + depth + normals", () =>
                {
                    StraightAlpha.Resolve(frame, rgba, Background.Transparent, mask);
                    DepthEncoding.ToMillimetres(frame, depth);
                    NormalEncoding.Encode(frame, normals);
                }));
            var copy = results[0];
            var all = results[results.Length - 1];
            Console.WriteLine($"  ratio all / copy: {all.Min / copy.Min:F2}× (fastest rounds), {all.Median / copy.Median:F2}× (median rounds)");
            Console.WriteLine();
        }

        static void PostProcessingLinearFloat()
        {
            var frame = SyntheticFrame.Sphere(OutputSize, Supersampling, linearFloatColour: true);
            var rgba = new byte[OutputSize * OutputSize * 4];
            var mask = new byte[OutputSize * OutputSize];
            var copyTarget = new float[frame.ColorLinear.Length];
            var maskCopy = new byte[frame.Mask.Length];
            Console.WriteLine("Colour from linear float RGBA (R32G32B32A32_SFloat readback), same frame:");
            var results = Interleaved(
                ("plain copy of colour + mask input (" + ((frame.ColorLinear.Length * 4L + frame.Mask.Length) / 1e6).ToString("F1") + " MB)", () =>
                {
                    Buffer.BlockCopy(frame.ColorLinear, 0, copyTarget, 0, copyTarget.Length * 4);
                    Buffer.BlockCopy(frame.Mask, 0, maskCopy, 0, maskCopy.Length);
                }),
                ("colour + alpha + mask image, one pass", () => StraightAlpha.Resolve(frame, rgba, Background.Transparent, mask)));
            Console.WriteLine($"  ratio: {results[1].Min / results[0].Min:F2}× (fastest rounds), {results[1].Median / results[0].Median:F2}× (median rounds)");
            Console.WriteLine();
        }

        const int Rounds = 31;

        struct Timing
        {
            public double Min;
            public double Median;
        }

        /// <summary>
        /// Runs every step once per round, in turn, so that load from other processes on a shared machine hits all
        /// of them alike; the fastest round is the least disturbed estimate.
        /// </summary>
        static Timing[] Interleaved(params (string Name, Action Run)[] steps)
        {
            var times = new List<double>[steps.Length];
            for (int i = 0; i < steps.Length; i++)
            {
                times[i] = new List<double>();
                steps[i].Run();
            }
            for (int round = 0; round < Rounds; round++)
            for (int i = 0; i < steps.Length; i++)
            {
                var watch = Stopwatch.StartNew();
                steps[i].Run();
                times[i].Add(watch.Elapsed.TotalMilliseconds);
            }
            var result = new Timing[steps.Length];
            for (int i = 0; i < steps.Length; i++)
            {
                times[i].Sort();
                result[i] = new Timing { Min = times[i][0], Median = times[i][Rounds / 2] };
                Console.WriteLine($"  {steps[i].Name,-50} {result[i].Min,7:F2} {result[i].Median,7:F2}");
            }
            return result;
        }

        static void Png(string title, byte[] rgba, ushort[] depth)
        {
            long rawBytes = rgba != null ? rgba.Length : depth.Length * 2L;
            Console.WriteLine($"PNG encode, {title}, raw {rawBytes / 1e6:F2} MB; single thread: fastest of {PngRounds} interleaved rounds:");
            var configs = new List<(PngCompression Compression, PngFilter Filter, Func<byte[]> Encode)>();
            foreach (PngCompression compression in Enum.GetValues(typeof(PngCompression)))
            foreach (PngFilter filter in Enum.GetValues(typeof(PngFilter)))
            {
                var c = compression;
                var f = filter;
                configs.Add((c, f, rgba != null
                    ? () => PngWriter.Encode(rgba, OutputSize, OutputSize, PngPixelFormat.Rgba8, c, f)
                    : () => PngWriter.EncodeGray16(depth, OutputSize, OutputSize, c, f)));
            }

            var best = new double[configs.Count];
            for (int i = 0; i < configs.Count; i++)
            {
                configs[i].Encode();
                best[i] = double.MaxValue;
            }
            for (int round = 0; round < PngRounds; round++)
            for (int i = 0; i < configs.Count; i++)
            {
                var watch = Stopwatch.StartNew();
                configs[i].Encode();
                best[i] = Math.Min(best[i], watch.Elapsed.TotalMilliseconds);
            }

            Console.WriteLine("  compression  filter     size (KB)   ms  1 thread (MB/s)  all cores (MB/s)  alloc/call (KB)");
            for (int i = 0; i < configs.Count; i++)
            {
                var (compression, filter, encode) = configs[i];
                int size = encode().Length;
                long before = GC.GetAllocatedBytesForCurrentThread();
                encode();
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                double parallel = AllCores(encode, perCore: 4);
                string marker = compression == PngWriter.DefaultCompression && filter == PngWriter.DefaultFilter ? "  <- default" : "";
                Console.WriteLine($"  {compression,-11}  {filter,-9}  {size / 1024.0,9:F1}  {best[i],5:F1}  {rawBytes / 1e6 / (best[i] / 1000),15:F0}  {parallel * rawBytes / 1e6,16:F0}  {(allocated - size) / 1024.0,15:F1}{marker}");
            }
            Console.WriteLine("  (alloc/call excludes the returned file; what remains is DeflateStream's own objects)");
            Console.WriteLine();
        }

        const int PngRounds = 7;

        /// <summary>Images per second with one encode job per core running at once.</summary>
        static double AllCores(Func<byte[]> encode, int perCore)
        {
            int jobs = Environment.ProcessorCount * perCore;
            Parallel.For(0, Environment.ProcessorCount, _ => encode());
            var watch = Stopwatch.StartNew();
            Parallel.For(0, jobs, new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount }, _ => encode());
            return jobs / watch.Elapsed.TotalSeconds;
        }

        static double Median(Action action, int runs = 25)
        {
            action();
            action();
            var times = new List<double>();
            for (int i = 0; i < runs; i++)
            {
                var watch = Stopwatch.StartNew();
                action();
                times.Add(watch.Elapsed.TotalMilliseconds);
            }
            times.Sort();
            return times[runs / 2];
        }
    }
}
