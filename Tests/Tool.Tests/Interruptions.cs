using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>Runs of the tool under a <see cref="FileFaultPlan"/>: counted, stopped (a simulated kill) or failing at one step.</summary>
    static class Interruptions
    {
        /// <summary>How many file operations (<see cref="FileOps"/>) a run of <paramref name="args"/> makes, and that run's result.</summary>
        public static int Steps(out ToolRun run, params string[] args)
        {
            var plan = FileFaultPlan.Counting();
            FileOps.Faults = plan;
            try
            {
                run = ToolRun.Of(args);
            }
            finally
            {
                FileOps.Faults = null;
            }
            return plan.Count;
        }

        /// <summary>Runs <paramref name="args"/> and "kills" it just before file operation <paramref name="step"/>: nothing after it happens.</summary>
        public static void StopAt(int step, params string[] args)
        {
            var plan = FileFaultPlan.StoppingAt(step);
            FileOps.Faults = plan;
            try
            {
                ToolRun.Of(args);
            }
            catch (SimulatedStopException)
            {
            }
            finally
            {
                FileOps.Faults = null;
            }
            Assert.That(plan.Stopped, Is.True, "step " + step + " was reached");
        }

        /// <summary>Runs <paramref name="args"/> with file operation <paramref name="step"/> throwing <paramref name="fault"/>.</summary>
        public static ToolRun FailAt(int step, Func<string, string, Exception> fault, params string[] args)
        {
            FileOps.Faults = FileFaultPlan.FailingAt(step, fault);
            try
            {
                return ToolRun.Of(args);
            }
            finally
            {
                FileOps.Faults = null;
            }
        }

        /// <summary>The names in <paramref name="folder"/>, to check that no working folder is left beside an output.</summary>
        public static string[] Entries(string folder) =>
            Directory.GetFileSystemEntries(folder).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToArray();

        /// <summary>True when <paramref name="text"/> holds a .NET stack trace line.</summary>
        public static bool HasStackTrace(string text) => text.Split('\n').Any(l => l.TrimStart().StartsWith("at ", StringComparison.Ordinal) && l.Contains("("));
    }
}
