using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Plans 100 000 views and writes the dataset's JSON files (the three transforms files and dataset_config.json)
    /// through the same write session a capture uses, into a temp folder deleted afterwards.
    /// </summary>
    static class TransformsBenchmark
    {
        // nerf_synthetic's proportions (100 / 100 / 200) scaled to 100 000 views, with its default formations.
        const int Train = 25000;
        const int Val = 25000;
        const int Test = 50000;
        const int Rounds = 5;

        public static void Run()
        {
            var settings = new DatasetSettings { Name = "bench" };
            settings.Train.Count = Train;
            settings.Val.Count = Val;
            settings.Test.Count = Test;
            var root = Path.Combine(Path.GetTempPath(), "nerf-bench-" + Guid.NewGuid().ToString("N"));
            Console.WriteLine($"Plan and write the transforms files for {Thousands(Train + Val + Test)} views (train {Thousands(Train)} semi-sphere, val {Thousands(Val)} random, test {Thousands(Test)} orbit),");
            Console.WriteLine($"single thread, 1 warm-up + {Rounds} rounds, fastest and median in ms:");
            try
            {
                var plan = new List<double>();
                var text = new List<double>();
                var write = new List<double>();
                long bytes = 0;
                var files = new List<(string Name, long Length)>();
                for (var round = 0; round <= Rounds; round++)
                {
                    var watch = Stopwatch.StartNew();
                    var built = CapturePlan.Build(settings, PlanTarget.AtOrigin);
                    var planMs = watch.Elapsed.TotalMilliseconds;

                    // The same JSON text in memory only, to split the write below into serialisation and disk.
                    var provenance = new Provenance(DateTime.UtcNow, null, "benchmark", imagesRendered: false);
                    watch.Restart();
                    DatasetConfigWriter.Write(built, provenance);
                    foreach (var split in DatasetSplits.All) BlenderTransformsWriter.Write(built, split);
                    var textMs = watch.Elapsed.TotalMilliseconds;

                    var folder = Path.Combine(root, "round-" + round);
                    watch.Restart();
                    var session = DatasetWriteSession.Begin(folder, OverwritePolicy.Never);
                    DatasetMetadataFiles.Write(session, built, provenance);
                    session.Commit();
                    var writeMs = watch.Elapsed.TotalMilliseconds;

                    files = Directory.GetFiles(folder).Select(f => (Path.GetFileName(f), new FileInfo(f).Length)).OrderBy(f => f.Item1, StringComparer.Ordinal).ToList();
                    bytes = files.Sum(f => f.Length);
                    Directory.Delete(folder, true);
                    if (round == 0) continue;
                    plan.Add(planMs);
                    text.Add(textMs);
                    write.Add(writeMs);
                }
                var total = plan.Zip(write, (p, w) => p + w).ToList();
                Print("CapturePlan.Build (poses, c2w matrices, file names)", plan);
                Print("JSON text + write + commit (DatasetMetadataFiles.Write)", write);
                Print("  of which the JSON text alone, in memory", text);
                Print("plan + write", total);
                Console.WriteLine($"  written: {bytes / 1e6:F1} MB in {files.Count} files ({string.Join(", ", files.Select(f => f.Name + " " + Size(f.Length)))})");
                Console.WriteLine($"  per view: {total.Min() * 1000 / (Train + Val + Test):F1} µs, {bytes / (double)(Train + Val + Test):F0} bytes; text + disk {bytes / 1e6 / (write.Min() / 1000):F0} MB/s");
            }
            finally
            {
                if (Directory.Exists(root)) Directory.Delete(root, true);
            }
            Console.WriteLine();
        }

        static string Thousands(int n) => n.ToString("N0", CultureInfo.InvariantCulture).Replace(",", " ");

        static string Size(long bytes) => bytes >= 100000 ? (bytes / 1e6).ToString("F1", CultureInfo.InvariantCulture) + " MB" : (bytes / 1e3).ToString("F1", CultureInfo.InvariantCulture) + " KB";

        static void Print(string name, List<double> times)
        {
            var sorted = times.OrderBy(t => t).ToList();
            Console.WriteLine($"  {name,-58} {sorted[0],8:F1} {sorted[sorted.Count / 2],8:F1}");
        }
    }
}
