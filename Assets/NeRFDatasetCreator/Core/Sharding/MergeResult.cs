using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>What <see cref="ShardMerger.Merge"/> did: either the merged folder, or every problem and nothing changed.</summary>
    public sealed class MergeResult
    {
        public MergeResult(string outputFolder, IReadOnlyList<ValidationProblem> problems, IReadOnlyList<string> warnings,
            IReadOnlyDictionary<string, int> framesPerSplit, int filesTransferred, IReadOnlyList<string> notes = null)
        {
            Notes = notes ?? new string[0];
            OutputFolder = outputFolder;
            Problems = problems;
            Warnings = warnings;
            FramesPerSplit = framesPerSplit;
            FilesTransferred = filesTransferred;
        }

        /// <summary>
        /// The result when this merge found an interrupted merge into the same output complete in its working folder and
        /// finished it (<see cref="Recovery"/>): the frames are counted from the merged transforms files.
        /// </summary>
        public static MergeResult FinishedEarlier(string output, IReadOnlyList<string> warnings, IReadOnlyList<string> notes)
        {
            var perSplit = new Dictionary<string, int>();
            foreach (var split in ViewCounts.SplitNames)
            {
                try
                {
                    // Counted as the file streams past (DatasetFolder): a merged split of 300 000 frames is not held.
                    var merged = DatasetFolder.ReadSplit(output, split, DatasetReadMode.Lenient, _ => { });
                    if (merged.HasFrameList) perSplit[split] = merged.FrameCount;
                }
                catch (System.Exception e) when (e is System.IO.IOException || e is System.UnauthorizedAccessException || e is SettingsFormatException) { }
            }
            return new MergeResult(output, new ValidationProblem[0], warnings, perSplit, 0, notes) { _finishedEarlier = true };
        }

        bool _finishedEarlier;

        public bool Succeeded => Problems.Count == 0;

        /// <summary>The merged dataset's folder; it exists only when <see cref="Succeeded"/>.</summary>
        public string OutputFolder { get; }

        /// <summary>Why the merge was refused or undone; empty on success. One line each, naming the split, view, file or shard.</summary>
        public IReadOnlyList<ValidationProblem> Problems { get; }

        /// <summary>Things left behind in the shard folders that do not stop the merge (stray files, per-shard extras).</summary>
        public IReadOnlyList<string> Warnings { get; }

        /// <summary>What merge found of earlier runs on the output: interrupted merges it finished or rolled back, leftover working folders.</summary>
        public IReadOnlyList<string> Notes { get; }

        public IReadOnlyDictionary<string, int> FramesPerSplit { get; }
        public int FilesTransferred { get; }

        /// <summary>The report as lines for a console or a log: problems first, then warnings, then a summary.</summary>
        public IEnumerable<string> Lines()
        {
            foreach (var n in Notes) yield return "note: " + n;
            foreach (var p in Problems) yield return "error: " + p;
            foreach (var w in Warnings) yield return "warning: " + w;
            if (_finishedEarlier)
            {
                yield return "merged " + string.Join(", ", FramesPerSplit.Select(kv => kv.Value + " " + kv.Key)) + " frames into " + OutputFolder + " (the interrupted earlier merge, now finished)";
                yield break;
            }
            yield return Succeeded
                ? "merged " + string.Join(", ", FramesPerSplit.Select(kv => kv.Value + " " + kv.Key)) + " frames (" + FilesTransferred + " files) into " + OutputFolder
                : "merge refused: " + Problems.Count + " problem(s); no file was changed.";
        }
    }
}
