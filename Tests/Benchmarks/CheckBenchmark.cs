using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// <c>nerf-dataset check</c> on a 300-view 800×800 dataset with depth, normals and masks (issue 21), and PNG decoding
    /// of its files, which the check spends most of its time on. The dataset is rendered once (the test scene of
    /// Core/Demo/AnalyticScene.cs, one ray per pixel through NeRF's ray formula, the plugin's own PNG writer) into
    /// a folder under the temp folder that later runs reuse. run-all decodes the same files with Pillow in the same run.
    /// </summary>
    static class CheckBenchmark
    {
        const int Size = 800, Views = 300;
        const string Version = "v1";

        public static string Folder => Path.Combine(Path.GetTempPath(), "nerf-check-benchmark-" + Size + "x" + Views + "-" + Version);

        /// <summary>The files whose decoding is compared with Pillow: the first views' colour, depth, normal and mask PNGs.</summary>
        public const int DecodeViews = 6;

        public static void Run(Action<string, double> record, Func<(string, Action)[], double[]> interleaved)
        {
            var folder = Prepare();
            Console.WriteLine($"Check of a {Views}-view {Size}×{Size} dataset with depth, normals and masks ({folder}); one run, s:");
            var cpu = Process.GetCurrentProcess().TotalProcessorTime;
            var wall = Stopwatch.StartNew();
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            wall.Stop();
            var used = (Process.GetCurrentProcess().TotalProcessorTime - cpu).TotalSeconds;
            Console.WriteLine($"  whole check (CPU)                                    {used,7:F2}");
            Console.WriteLine($"  whole check (wall clock)                             {wall.Elapsed.TotalSeconds,7:F2}");
            Console.WriteLine($"  of which reading + PNG decoding (wall clock)         {report.DecodeSeconds,7:F2}");
            foreach (var pair in report.CheckSeconds)
            {
                Console.WriteLine($"    in {pair.Key + " (wall clock)",-48} {pair.Value,7:F2}");
                record("check.in." + pair.Key.Replace(' ', '-') + ".s", pair.Value);
            }
            Console.WriteLine($"  views checked {report.ViewsChecked}, failed: {report.Failed} ({report.Problems.Count} problems)");
            foreach (var line in report.SummaryLines) Console.WriteLine("    " + line);
            // The decoding alone, in CPU time like the whole: every PNG the check's first pass reads, read and decoded once.
            var pngFiles = Directory.GetFiles(folder, "*.png", SearchOption.AllDirectories);
            var decodeCpu = Process.GetCurrentProcess().TotalProcessorTime;
            foreach (var file in pngFiles) PngReader.Read(file);
            var decodeUsed = (Process.GetCurrentProcess().TotalProcessorTime - decodeCpu).TotalSeconds;
            Console.WriteLine($"  reading + decoding its {pngFiles.Length} PNGs once (CPU)           {decodeUsed,7:F2}  ({100 * decodeUsed / used:F0} % of the check)");
            record("check.decode.cpu.s", decodeUsed);
            record("check.cpu.s", used);
            record("check.wall.s", wall.Elapsed.TotalSeconds);
            record("check.decode.s", report.DecodeSeconds);
            record("check.ms-per-view", 1000 * used / Math.Max(1, report.ViewsChecked));

            Console.WriteLine($"PNG decoding (PngReader.Decode from bytes in memory) of the first {DecodeViews} views' files; ms per image, MB/s of decoded pixels:");
            foreach (var (key, suffix) in Kinds)
            {
                var files = Enumerable.Range(0, DecodeViews).Select(i => File.ReadAllBytes(Path.Combine(folder, "train", "r_" + i + suffix))).ToArray();
                var rawBytes = PngReader.Decode(files[0], "x").Samples.Length;
                var ms = interleaved(new (string, Action)[] { ("decode " + key, () => { foreach (var f in files) PngReader.Decode(f, "x"); }) })[0] / files.Length;
                Console.WriteLine($"  {key,-8} {ms,8:F2} ms  {rawBytes / 1e3 / ms,7:F0} MB/s");
                record("check.png." + key + ".ms", ms);
                record("check.png." + key + ".mbs", rawBytes / 1e3 / ms);
            }
            Console.WriteLine();
        }

        public static readonly (string Key, string Suffix)[] Kinds =
        {
            ("rgba", ".png"), ("depth", "_depth_0000.png"), ("normal", "_normal_0000.png"), ("mask", "_mask_0000.png"),
        };

        /// <summary>The dataset folder, rendered first if a previous run has not left it complete.</summary>
        static string Prepare()
        {
            var folder = Folder;
            var done = Path.Combine(folder, "complete");
            if (File.Exists(done)) return folder;
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
            var started = Stopwatch.StartNew();
            var settings = new DatasetSettings { Name = "check-benchmark", Width = Size, Height = Size };
            settings.Train.Count = Views - 2;
            settings.Train.Formation.Kind = FormationKind.Sphere;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            foreach (var split in new[] { settings.Train, settings.Val, settings.Test })
            {
                split.Depth = ExtraOutput.Png;
                split.Normal = ExtraOutput.Png;
                split.Mask = true;
            }
            var plan = CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 1.2));
            var scene = AnalyticScene.Layout(plan.Normalisation, Vector3d.Zero);
            foreach (var split in DatasetSplits.Names) Directory.CreateDirectory(Path.Combine(folder, split));
            foreach (var split in DatasetSplits.All)
                File.WriteAllText(Path.Combine(folder, DatasetLayout.TransformsFileName(split)), BlenderTransformsWriter.Write(plan, split));
            var f = plan.Intrinsics.FlX;
            foreach (var view in plan.Views)
            {
                var m = view.TransformMatrix;
                var rgba = new byte[Size * Size * 4];
                var mask = new byte[Size * Size];
                var depth = new ushort[Size * Size];
                var normals = new byte[Size * Size * 3];
                for (var y = 0; y < Size; y++)
                    for (var x = 0; x < Size; x++)
                    {
                        // NeRF's ray through the pixel centre; its camera-space z is −1, so t is the z-depth.
                        var dc = new Vector3d((x + 0.5 - Size / 2.0) / f, -(y + 0.5 - Size / 2.0) / f, -1);
                        var d = m.MultiplyVector(dc);
                        if (!scene.Trace(m.Translation, d, 0, out var t, out var n, out var colour, out var alpha)) continue;
                        var p = y * Size + x;
                        for (var c = 0; c < 3; c++) rgba[4 * p + c] = (byte)(255 * colour[c] * (0.4 + 0.6 * Math.Abs(n.Z)));
                        rgba[4 * p + 3] = (byte)Math.Round(255 * alpha);
                        mask[p] = 255;
                        depth[p] = (ushort)Math.Min(65535, Math.Max(1, Math.Round(t * 1000)));
                        normals[3 * p] = NormalEncoding.Component((float)n.X);
                        normals[3 * p + 1] = NormalEncoding.Component((float)n.Y);
                        normals[3 * p + 2] = NormalEncoding.Component((float)n.Z);
                    }
                File.WriteAllBytes(Path.Combine(folder, view.Files.Single(k => k.Kind == DatasetFileKind.Color).RelativePath), PngWriter.Encode(rgba, Size, Size, PngPixelFormat.Rgba8));
                File.WriteAllBytes(Path.Combine(folder, view.Files.Single(k => k.Kind == DatasetFileKind.MaskPng).RelativePath), PngWriter.Encode(mask, Size, Size, PngPixelFormat.Gray8));
                File.WriteAllBytes(Path.Combine(folder, view.Files.Single(k => k.Kind == DatasetFileKind.DepthPng).RelativePath), PngWriter.EncodeGray16(depth, Size, Size));
                File.WriteAllBytes(Path.Combine(folder, view.Files.Single(k => k.Kind == DatasetFileKind.NormalPng).RelativePath), PngWriter.Encode(normals, Size, Size, PngPixelFormat.Rgb8));
            }
            File.WriteAllText(done, "rendered in " + started.Elapsed.TotalSeconds.ToString("F0", System.Globalization.CultureInfo.InvariantCulture) + " s\n");
            Console.WriteLine($"(rendered the check benchmark's dataset in {started.Elapsed.TotalSeconds:F0} s)");
            return folder;
        }
    }
}
