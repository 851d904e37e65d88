using System;
using System.Globalization;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes a dataset safely: everything goes into a temporary sibling folder <c>&lt;name&gt;.partial-&lt;stamp&gt;~</c>
    /// (the '~' keeps Unity from importing it even under Assets), and only <see cref="Commit"/> moves it to the
    /// final name — so a cancelled or failed run never leaves a partial dataset under the final name, and
    /// <see cref="PartialFolder"/> says where its files are. An existing dataset is replaced only under
    /// <see cref="OverwritePolicy.Replace"/>, and only after the new one is complete.
    /// </summary>
    public sealed class DatasetWriteSession
    {
        bool _committed;

        DatasetWriteSession(string finalFolder, string workingFolder, OverwritePolicy policy)
        {
            FinalFolder = finalFolder;
            WorkingFolder = workingFolder;
            Policy = policy;
        }

        public string FinalFolder { get; }

        /// <summary>Where the run writes its files until <see cref="Commit"/>.</summary>
        public string WorkingFolder { get; }

        public OverwritePolicy Policy { get; }

        public bool IsCommitted => _committed;

        /// <summary>Where an unfinished run's files are (null once committed).</summary>
        public string PartialFolder => _committed ? null : WorkingFolder;

        /// <summary>
        /// Checks <paramref name="datasetFolder"/> (<see cref="SafeOutput.CheckOutputFolder"/>; throws
        /// <see cref="InvalidParameterException"/> with every problem) and creates the working folder.
        /// </summary>
        public static DatasetWriteSession Begin(string datasetFolder, OverwritePolicy policy, string projectRoot = null, DateTime? now = null)
        {
            var problems = SafeOutput.CheckOutputFolder(datasetFolder, projectRoot, policy);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            var full = Path.GetFullPath(datasetFolder).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var parent = Path.GetDirectoryName(full);
            Directory.CreateDirectory(parent);
            var stamp = (now ?? DateTime.UtcNow).ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture);
            var working = Path.Combine(parent, Path.GetFileName(full) + ".partial-" + stamp + "-" + Guid.NewGuid().ToString("N").Substring(0, 8) + "~"); // "N" is 32 hex digits: invariant
            Directory.CreateDirectory(working);
            return new DatasetWriteSession(full, working, policy);
        }

        /// <summary>The absolute path in the working folder of a dataset-relative path such as <c>train/r_0.png</c>.</summary>
        public string PathOf(string relativePath)
        {
            var path = Path.GetFullPath(Path.Combine(WorkingFolder, relativePath.Replace('/', Path.DirectorySeparatorChar)));
            if (!path.StartsWith(WorkingFolder + Path.DirectorySeparatorChar, StringComparison.Ordinal))
                throw new ArgumentException("'" + relativePath + "' leaves the dataset folder.", nameof(relativePath));
            return path;
        }

        /// <summary>Writes a UTF-8 text file (no byte-order mark) at a dataset-relative path, creating its folder.</summary>
        public void WriteText(string relativePath, string text)
        {
            var path = PathOf(relativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            File.WriteAllText(path, text, new System.Text.UTF8Encoding(false));
        }

        /// <summary>
        /// Moves the complete dataset to its final name. Under <see cref="OverwritePolicy.Replace"/> an existing
        /// dataset there is first moved aside and deleted only after the move succeeded (restored if it failed).
        /// </summary>
        public void Commit()
        {
            if (_committed) throw new InvalidOperationException("The dataset was already moved into place.");
            string aside = null;
            if (Directory.Exists(FinalFolder) || File.Exists(FinalFolder))
            {
                var empty = Directory.Exists(FinalFolder) && Directory.GetFileSystemEntries(FinalFolder).Length == 0;
                if (!empty && (Policy != OverwritePolicy.Replace || !SafeOutput.LooksLikeDataset(FinalFolder)))
                    throw new IOException(FinalFolder + " appeared while the dataset was being written and is not replaced; the new dataset is complete in " + WorkingFolder + ".");
                aside = FinalFolder + ".replaced-" + Guid.NewGuid().ToString("N").Substring(0, 8) + "~";
                Directory.Move(FinalFolder, aside);
            }
            try
            {
                Directory.Move(WorkingFolder, FinalFolder);
            }
            catch
            {
                if (aside != null && !Directory.Exists(FinalFolder)) Directory.Move(aside, FinalFolder);
                throw;
            }
            _committed = true;
            if (aside != null) Directory.Delete(aside, true);
        }

        /// <summary>A sentence for a cancelled or failed run's log: where its partial files are.</summary>
        public string DescribeAbandoned() =>
            _committed ? "The dataset is complete in " + FinalFolder + "." :
                "The dataset was not finished; nothing was written to " + FinalFolder + ". Partial files are in " + WorkingFolder + " (delete it, or keep it to inspect).";

        /// <summary>Deletes the working folder of an unfinished run (when the user does not want the partial files).</summary>
        public void DiscardPartialFiles()
        {
            if (!_committed && Directory.Exists(WorkingFolder)) Directory.Delete(WorkingFolder, true);
        }
    }
}
