using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset clean &lt;folder&gt; [--dry-run]</c>: finishes or rolls back the interrupted operations on the
    /// outputs in the folder, then removes the leftover working folders (<see cref="LeftoverCleaner"/>), printing each
    /// with its size. Folders it cannot prove the tool wrote are listed as "not ours, left alone". Exit 0 (also when
    /// there was nothing to clean, or only folders that are not ours), 1 when a leftover had to be kept or a journal was refused.
    /// </summary>
    public static class CleanCommand
    {
        public static int Run(string folder, bool dryRun, TextWriter stdout, TextWriter stderr)
        {
            LeftoverCleaner.Result result;
            try
            {
                result = LeftoverCleaner.Clean(folder, dryRun);
            }
            catch (InvalidParameterException e)
            {
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                return ToolExitCodes.UsageError;
            }
            foreach (var note in result.Recovered) stdout.WriteLine(note);
            foreach (var removed in result.Removed) stdout.WriteLine((dryRun ? "would remove " : "removed ") + removed);
            foreach (var refused in result.Refused) stderr.WriteLine("error: " + refused);
            foreach (var kept in result.Kept) stderr.WriteLine("kept " + kept);
            foreach (var alone in result.LeftAlone) stdout.WriteLine("not ours, left alone: " + alone);
            if (result.Recovered.Count + result.Removed.Count + result.Kept.Count + result.Refused.Count + result.LeftAlone.Count == 0)
                stdout.WriteLine("nothing to clean in " + Path.GetFullPath(folder) + ": no working folder is left over.");
            return result.Kept.Count + result.Refused.Count > 0 ? ToolExitCodes.Failure : ToolExitCodes.Success;
        }
    }
}
