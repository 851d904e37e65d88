using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Files written into an output folder that may already hold other files (convert writes <c>transforms.json</c>
    /// into the dataset itself): each goes first into a working folder inside the output
    /// (<c>.convert.partial-&lt;stamp&gt;~</c>), and <see cref="Commit"/> moves them into place — renames within one
    /// file system — once all are complete. The journal lists them, so a run killed while writing is rolled back and
    /// one killed while moving is finished by the next run on the same output (<see cref="Recovery"/>).
    /// Nothing is ever overwritten.
    /// </summary>
    public sealed class StagedOutput
    {
        readonly OperationJournal _journal;
        readonly List<string> _files = new List<string>();

        StagedOutput(string output, string working, OperationJournal journal)
        {
            Output = output;
            Working = working;
            _journal = journal;
        }

        public string Output { get; }
        public string Working { get; }

        /// <summary>True once <see cref="Commit"/> has started moving files (a failure then is finished by the next run, not undone).</summary>
        public bool Placing { get; private set; }

        public static StagedOutput Begin(string output, string operation, DateTime? now = null)
        {
            output = Path.GetFullPath(output).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var created = !Directory.Exists(output);
            FileOps.CreateDirectory(output);
            var working = WorkingFolders.NewConvert(output, now ?? DateTime.UtcNow);
            var journal = new OperationJournal { Operation = operation, Output = output, CreatedOutput = created };
            OperationOwner.Register(working); // before the journal names this process: no recovery here takes it for an ended run
            WorkingFolders.Create(working, journal); // born with its journal: never an owner-less empty folder
            return new StagedOutput(output, working, journal);
        }

        /// <summary>Writes a new text file that will be at <paramref name="finalPath"/> (inside the output).</summary>
        public void WriteNewText(string finalPath, string text) => FileOps.WriteNewText(Stage(finalPath), text);

        /// <summary>Writes a new binary file that will be at <paramref name="finalPath"/> (inside the output).</summary>
        public void WriteNewBytes(string finalPath, byte[] bytes) => FileOps.WriteNewBytes(Stage(finalPath), bytes);

        /// <summary>Writes a new file that will be at <paramref name="finalPath"/>, streamed by <paramref name="write"/>.</summary>
        public void WriteNew(string finalPath, Action<Stream> write) => FileOps.WriteNew(Stage(finalPath), write);

        /// <summary>Copies <paramref name="from"/> to what will be <paramref name="finalPath"/>.</summary>
        public void Copy(string from, string finalPath) => FileOps.CopyFile(from, Stage(finalPath));

        /// <summary>Hard-links (else copies) <paramref name="from"/> to what will be <paramref name="finalPath"/>; true when linked.</summary>
        public bool LinkOrCopy(string from, string finalPath) => FileOps.LinkOrCopyFile(from, Stage(finalPath));

        string Stage(string finalPath)
        {
            var relative = Path.GetRelativePath(Output, Path.GetFullPath(finalPath));
            if (relative.StartsWith("..", StringComparison.Ordinal) || Path.IsPathRooted(relative))
                throw new ArgumentException(finalPath + " is not inside " + Output + ".", nameof(finalPath));
            var staged = Path.Combine(Working, relative);
            FileOps.CreateDirectory(Path.GetDirectoryName(staged));
            _files.Add(relative.Replace(Path.DirectorySeparatorChar, '/'));
            return staged;
        }

        /// <summary>Moves every file into place (none may exist there: never overwritten) and removes the working folder.</summary>
        public void Commit()
        {
            // A destination that appeared while this run was writing (another convert into the same output finished
            // first) is found before anything is placed, so this run is abandoned whole: its own working folder goes.
            foreach (var file in _files)
            {
                var to = Path.Combine(Output, file.Replace('/', Path.DirectorySeparatorChar));
                if (File.Exists(to) || Directory.Exists(to)) throw Appeared(to);
            }
            _journal.Files.AddRange(_files);
            _journal.State = OperationJournal.Committing;
            _journal.Save(Working);
            Placing = true;
            OperationOwner.Register(Output); // the journal moves there below, still this run's
            try
            {
                var placed = 0;
                foreach (var file in _files)
                {
                    var to = Path.Combine(Output, file.Replace('/', Path.DirectorySeparatorChar));
                    if (File.Exists(to) || Directory.Exists(to))
                    {
                        // Another convert into the same output ran to its end between the check above and here (it leaves
                        // a running run's folder alone, OperationOwner): with nothing of this run placed, this run is
                        // abandoned whole, like one that found the conflict before placing.
                        if (placed == 0)
                        {
                            Placing = false;
                            throw Appeared(to);
                        }
                        throw new IOException(to + " appeared while convert was writing; convert never overwrites. The remaining files are in " + Working + ".");
                    }
                    FileOps.CreateDirectory(Path.GetDirectoryName(to));
                    try
                    {
                        FileOps.MoveFile(Path.Combine(Working, file.Replace('/', Path.DirectorySeparatorChar)), to);
                    }
                    catch (IOException) when (placed == 0 && (File.Exists(to) || Directory.Exists(to)))
                    {
                        Placing = false; // the other convert won between the check and the move: nothing of this run is placed
                        throw Appeared(to);
                    }
                    placed++;
                }
                // Everything is in place. The journal moves out to the output first, so that a run killed while the emptied
                // working folder is being deleted (the journal possibly unlinked already) still leaves a record saying the
                // convert was complete: the next run finishes it (Recovery's own-journal case) instead of refusing to
                // overwrite the files this run placed.
                FileOps.MoveFile(OperationJournal.PathIn(Working), OperationJournal.PathIn(Output));
                try
                {
                    FileOps.DeleteDirectory(Working);
                }
                catch (DirectoryNotFoundException)
                {
                    // Emptied and without its journal, it may already have been removed by another run's recovery (as a
                    // folder killed before its journal was written): what was to be done is done.
                }
                OperationJournal.Delete(Output);
            }
            finally
            {
                // Finished, or failed while placing: either way this run is over, and the next run on the output finishes it.
                OperationOwner.Release(Output);
                OperationOwner.Release(Working);
            }
        }

        static InvalidParameterException Appeared(string path) => new InvalidParameterException(new[]
        {
            new ValidationProblem("outDir", path, "appeared while this convert was writing (another convert into the same output finished first); convert never overwrites, so this run placed nothing and removed its own working folder.",
                "Use the files already there, or delete them and run convert again."),
        });

        /// <summary>Undoes an operation that failed before <see cref="Commit"/>: the working folder goes, and the output if this created it and it is empty.</summary>
        public void Abandon()
        {
            try
            {
                if (Directory.Exists(Working)) FileOps.DeleteDirectory(Working);
                if (_journal.CreatedOutput && Directory.Exists(Output) && !Directory.EnumerateFileSystemEntries(Output).Any()) FileOps.DeleteDirectory(Output);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                // Left with its journal: the next run on this output rolls it back.
            }
            finally
            {
                OperationOwner.Release(Working);
            }
        }
    }
}
