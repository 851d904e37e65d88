using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes a dataset safely: everything goes into a temporary sibling folder <c>&lt;name&gt;.partial-&lt;stamp&gt;~</c>
    /// (the '~' keeps Unity from importing it even under Assets), and only <see cref="Commit"/> moves it to the
    /// final name — so a cancelled or failed run never leaves a partial dataset under the final name, and
    /// <see cref="PartialFolder"/> says where its files are. An existing dataset is replaced only under
    /// <see cref="OverwritePolicy.Replace"/>, and only after the new one is complete. The working folder holds a journal
    /// (<see cref="OperationJournal"/>), so the next session on the same folder finishes or rolls back a run killed
    /// while committing (<see cref="Recovery"/>); the capture and <c>nerf-dataset plan</c> both write through this class.
    /// </summary>
    public sealed class DatasetWriteSession
    {
        bool _committed;

        DatasetWriteSession(string finalFolder, string workingFolder, OverwritePolicy policy, bool rendersImages)
        {
            RendersImages = rendersImages;
            FinalFolder = finalFolder;
            WorkingFolder = workingFolder;
            Policy = policy;
        }

        public string FinalFolder { get; }

        /// <summary>Where the run writes its files until <see cref="Commit"/>.</summary>
        public string WorkingFolder { get; }

        public OverwritePolicy Policy { get; }

        /// <summary>False for a run that writes no images (a plan): it never replaces a rendered dataset (<see cref="OwnDataset.WhyNotReplaceable"/>).</summary>
        public bool RendersImages { get; }

        public bool IsCommitted => _committed;

        /// <summary>Where an unfinished run's files are (null once committed).</summary>
        public string PartialFolder => _committed ? null : WorkingFolder;

        /// <summary>
        /// What <see cref="Begin"/> found of earlier runs on this output: one sentence per interrupted operation it
        /// finished or rolled back (<see cref="Recovery"/>).
        /// </summary>
        public IReadOnlyList<RecoveryNote> Recovered { get; private set; } = Array.Empty<RecoveryNote>();

        /// <summary>Working folders of earlier runs on this output that are still there (reported, removed by <c>nerf-dataset clean</c>).</summary>
        public IReadOnlyList<Leftover> Leftovers { get; private set; } = Array.Empty<Leftover>();

        /// <summary>
        /// Finishes or rolls back an interrupted earlier run on <paramref name="datasetFolder"/> (<see cref="Recovered"/>),
        /// checks it (<see cref="SafeOutput.CheckOutputFolder"/>; throws <see cref="InvalidParameterException"/> with
        /// every problem, naming the folder <paramref name="field"/>, as the user gave it) and creates the working folder with its journal.
        /// </summary>
        public static DatasetWriteSession Begin(string datasetFolder, OverwritePolicy policy, string projectRoot = null, DateTime? now = null,
            string field = "outputFolder", bool rendersImages = true)
        {
            var recovered = IsUsablePath(datasetFolder) ? Recovery.Run(datasetFolder) : Array.Empty<RecoveryNote>();
            var problems = SafeOutput.CheckOutputFolder(datasetFolder, projectRoot, policy, field, rendersImages);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            var full = Path.GetFullPath(datasetFolder).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var parent = Path.GetDirectoryName(full);
            FileOps.CreateDirectory(parent);
            var working = WorkingFolders.NewPartial(full, now ?? DateTime.UtcNow);
            // Registered before the journal names this process, so that no recovery here takes it for an ended run; born
            // with its journal, so that no recovery in another process takes it for a run killed at birth (WorkingFolders.Create).
            OperationOwner.Register(working);
            WorkingFolders.Create(working, new OperationJournal { Operation = "write", Output = full });
            return new DatasetWriteSession(full, working, policy, rendersImages) { Recovered = recovered, Leftovers = Leftover.Of(full, working) };
        }

        static bool IsUsablePath(string folder)
        {
            try
            {
                return !string.IsNullOrWhiteSpace(folder) && PathLimits.Check(Path.GetFullPath(folder), "outputFolder") == null;
            }
            catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is PathTooLongException)
            {
                return false;
            }
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
            FileOps.CreateDirectory(Path.GetDirectoryName(path));
            FileOps.WriteText(path, text);
        }

        /// <summary>Like <see cref="WriteText(string, string)"/>, with the text streamed by <paramref name="write"/>.</summary>
        public void WriteText(string relativePath, Action<TextWriter> write)
        {
            var path = PathOf(relativePath);
            FileOps.CreateDirectory(Path.GetDirectoryName(path));
            FileOps.WriteText(path, write);
        }

        /// <summary>Writes a binary file at a dataset-relative path as <paramref name="write"/> streams it, creating its folder.</summary>
        public void WriteBytes(string relativePath, Action<Stream> write)
        {
            var path = PathOf(relativePath);
            FileOps.CreateDirectory(Path.GetDirectoryName(path));
            FileOps.WriteStream(path, write);
        }

        /// <summary>
        /// Moves the complete dataset to its final name. Under <see cref="OverwritePolicy.Replace"/> an existing
        /// dataset there — only one this plugin provably wrote (<see cref="OwnDataset"/>) — is first moved aside and
        /// deleted only after the move succeeded (restored if it failed). The journal records each step, so a run
        /// killed anywhere in between is finished by the next one (<see cref="Recovery"/>).
        /// </summary>
        public void Commit()
        {
            if (_committed) throw new InvalidOperationException("The dataset was already moved into place.");
            string aside = null;
            if (Directory.Exists(FinalFolder) || File.Exists(FinalFolder))
            {
                var empty = Directory.Exists(FinalFolder) && Directory.GetFileSystemEntries(FinalFolder).Length == 0;
                if (!empty && (Policy != OverwritePolicy.Replace || OwnDataset.WhyNotReplaceable(FinalFolder, RendersImages) != null))
                    throw new IOException(FinalFolder + " appeared while the dataset was being written and is not replaced; the new dataset is complete in " + WorkingFolder + ".");
                aside = WorkingFolders.NewReplaced(FinalFolder);
            }
            new OperationJournal { Operation = "write", Output = FinalFolder, State = OperationJournal.Committing, Aside = aside }.Save(WorkingFolder);
            // Once moved, the journal is in the final folder until the clean-up below is done: still this run's.
            OperationOwner.Register(FinalFolder);
            try
            {
                if (aside != null) FileOps.MoveDirectory(FinalFolder, aside);
                try
                {
                    FileOps.MoveDirectory(WorkingFolder, FinalFolder);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    if (aside != null && !Directory.Exists(FinalFolder)) FileOps.MoveDirectory(aside, FinalFolder);
                    new OperationJournal { Operation = "write", Output = FinalFolder }.Save(WorkingFolder);
                    throw;
                }
                _committed = true;
                if (aside != null) FileOps.DeleteDirectory(aside);
                OperationJournal.Delete(FinalFolder);
            }
            finally
            {
                OperationOwner.Release(FinalFolder);
                if (_committed) OperationOwner.Release(WorkingFolder);
            }
        }

        /// <summary>
        /// The run ended without <see cref="Commit"/> (failed or cancelled): its partial folder stays, and from now on it
        /// is a leftover that recovery reports and <c>nerf-dataset clean</c> may remove, not a run in progress.
        /// </summary>
        public void End()
        {
            if (!_committed) OperationOwner.Release(WorkingFolder);
        }

        /// <summary>A sentence for a cancelled or failed run's log: where its partial files are.</summary>
        public string DescribeAbandoned() =>
            _committed ? "The dataset is complete in " + FinalFolder + "." :
                "The dataset was not finished; nothing was written to " + FinalFolder + ". Partial files are in " + WorkingFolder + " (delete it, or keep it to inspect).";

        /// <summary>Deletes the working folder of an unfinished run (when the user does not want the partial files).</summary>
        public void DiscardPartialFiles()
        {
            if (!_committed && Directory.Exists(WorkingFolder)) FileOps.DeleteDirectory(WorkingFolder);
            End();
        }
    }
}
