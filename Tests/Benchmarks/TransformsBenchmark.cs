using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Plans the largest dataset the settings allow (3 × 100 000 views) and writes its JSON files (the three transforms
    /// files, streamed, and dataset_config.json) through the same write session a capture uses, into a temp folder
    /// deleted afterwards. Peak memory is the process's peak working set, meaningful when this runs alone
    /// (--only plan), as run-all does.
    /// </summary>
    static class TransformsBenchmark
    {
        // Every split at its maximum (DatasetSettings.MaxViews), with the default formations.
        const int Train = DatasetSettings.MaxViews;
        const int Val = DatasetSettings.MaxViews;
        const int Test = DatasetSettings.MaxViews;
        const int Rounds = 3;

        public static void Run(Action<string, double> record)
        {
            var settings = new DatasetSettings { Name = "bench" };
            settings.Train.Count = Train;
            settings.Val.Count = Val;
            settings.Test.Count = Test;
            var root = Path.Combine(Path.GetTempPath(), "nerf-bench-" + Guid.NewGuid().ToString("N"));
            Console.WriteLine($"Plan and write the JSON files for {Thousands(Train + Val + Test)} views (train {Thousands(Train)} semi-sphere, val {Thousands(Val)} random, test {Thousands(Test)} orbit),");
            Console.WriteLine($"single thread, 1 warm-up + {Rounds} rounds, fastest in ms of wall time (and of this process's CPU time, which other load on the machine disturbs less):");
            try
            {
                double plan = double.MaxValue, write = double.MaxValue, total = double.MaxValue, cpu = double.MaxValue;
                double planCpu = double.MaxValue, writeCpu = double.MaxValue;
                var process = Process.GetCurrentProcess();
                long bytes = 0;
                int files = 0;
                for (var round = 0; round <= Rounds; round++)
                {
                    // Each round starts clean, as a capture in a fresh editor would: the peak is one plan's, not two.
                    GC.Collect();
                    GC.WaitForPendingFinalizers();
                    process.Refresh();
                    var cpuStart = process.TotalProcessorTime;
                    var watch = Stopwatch.StartNew();
                    var folder = Path.Combine(root, "round-" + round.ToString(CultureInfo.InvariantCulture));
                    PlanAndWrite(settings, folder, watch, process, cpuStart, out var planMs, out var planCpuMs, out var writeMs);
                    process.Refresh();
                    var cpuMs = (process.TotalProcessorTime - cpuStart).TotalMilliseconds;

                    bytes = 0;
                    files = 0;
                    foreach (var file in Directory.GetFiles(folder))
                    {
                        bytes += new FileInfo(file).Length;
                        files++;
                    }
                    Directory.Delete(folder, true);
                    if (round == 0) continue;
                    plan = Math.Min(plan, planMs);
                    write = Math.Min(write, writeMs);
                    total = Math.Min(total, planMs + writeMs);
                    cpu = Math.Min(cpu, cpuMs);
                    planCpu = Math.Min(planCpu, planCpuMs);
                    writeCpu = Math.Min(writeCpu, cpuMs - planCpuMs);
                }
                long peak = Process.GetCurrentProcess().PeakWorkingSet64;
                Console.WriteLine($"  CapturePlan.Build (poses, c2w matrices, file names)         {plan,8:F0}  ({planCpu:F0} ms CPU)");
                Console.WriteLine($"  JSON streamed to the working folder + commit                {write,8:F0}  ({writeCpu:F0} ms CPU)");
                Console.WriteLine($"  plan + write                                                {total,8:F0}  ({cpu:F0} ms CPU)");
                Console.WriteLine($"  written: {bytes / 1e6:F1} MB in {files} files; peak working set of this process: {peak / 1e6:F0} MB");
                record("plan.build.ms", plan);
                record("plan.write.ms", write);
                record("plan.total.ms", total);
                record("plan.cpu.ms", cpu);
                record("plan.build.cpu.ms", planCpu);
                record("plan.write.cpu.ms", writeCpu);
                record("plan.peak.mb", peak / 1e6);
                record("plan.written.mb", bytes / 1e6);
            }
            finally
            {
                if (Directory.Exists(root)) Directory.Delete(root, true);
            }
            Console.WriteLine();
        }

        // A method of its own, so that nothing in the caller's frame keeps the plan alive into the next round's collection.
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        static void PlanAndWrite(DatasetSettings settings, string folder, Stopwatch watch, Process process, TimeSpan cpuStart,
            out double planMs, out double planCpuMs, out double writeMs)
        {
            var built = CapturePlan.Build(settings, PlanTarget.AtOrigin);
            planMs = watch.Elapsed.TotalMilliseconds;
            process.Refresh();
            planCpuMs = (process.TotalProcessorTime - cpuStart).TotalMilliseconds;

            var provenance = new Provenance(DateTime.UtcNow, null, "benchmark", imagesRendered: false);
            watch.Restart();
            var session = DatasetWriteSession.Begin(folder, OverwritePolicy.Never);
            DatasetMetadataFiles.Write(session, built, provenance);
            session.Commit();
            writeMs = watch.Elapsed.TotalMilliseconds;
        }

        static string Thousands(int n) => n.ToString("N0", CultureInfo.InvariantCulture).Replace(",", " ");
    }
}
