using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The out folder's rule: evaluation writes <c>metrics.json</c>, <c>report.html</c> and <c>errors/&lt;name&gt;_error.png</c>
    /// and nothing else. It writes into a new or empty folder, or replaces an earlier evaluation's files in a folder that
    /// holds only those and whose metrics.json this tool wrote — or whose journal (written first, removed last) names a
    /// run that has ended: a killed evaluation's folder. Any other file there, a folder another evaluation is writing, or
    /// a folder really inside the dataset (links followed) is refused before anything is written.
    /// </summary>
    public static class EvaluationOutput
    {
        public const string ErrorFolder = "errors";
        public const string ErrorSuffix = "_error.png";

        public static void Prepare(string outFolder, string datasetRoot)
        {
            var full = Path.GetFullPath(outFolder);
            // The real path, every link followed: --out through a link into the dataset is inside it (SafeOutput's one rule).
            var inside = SafeOutput.WhyInsideDataset(full, datasetRoot);
            if (inside != null)
                throw Refuse(full, inside + "; evaluation never adds files to a dataset.", "Pass --out <folder> outside the dataset.");
            if (File.Exists(full)) throw Refuse(full, "is a file.", "Pass --out <folder>, a folder that does not exist yet or an earlier evaluation's.");
            if (!Directory.Exists(full))
            {
                FileOps.CreateDirectory(full);
                FileOps.CreateDirectory(Path.Combine(full, ErrorFolder));
                MarkRunning(full);
                return;
            }
            var strangers = new List<string>();
            foreach (var entry in Directory.GetFileSystemEntries(full))
            {
                var name = Path.GetFileName(entry);
                if (File.Exists(entry) && !PathSafety.IsLink(entry) && IsOwnName(name)) continue;
                if (Directory.Exists(entry) && name == ErrorFolder && !PathSafety.IsLink(entry))
                {
                    strangers.AddRange(Directory.GetFileSystemEntries(entry).Where(e => !(File.Exists(e) && e.EndsWith(ErrorSuffix, StringComparison.Ordinal))).Select(e => ErrorFolder + "/" + Path.GetFileName(e)));
                    continue;
                }
                strangers.Add(name);
            }
            if (strangers.Count > 0)
                throw Refuse(full, "holds " + string.Join(", ", strangers.Take(3)) + (strangers.Count > 3 ? " and " + (strangers.Count - 3) + " more" : "") + ", which evaluation did not write; it never overwrites or deletes what it did not write.",
                    "Pass --out <folder>, a new folder or an earlier evaluation's.");
            var metrics = Path.Combine(full, MetricsJson.FileName);
            var hasAny = Directory.GetFiles(full).Length > 0 || (Directory.Exists(Path.Combine(full, ErrorFolder)) && Directory.GetFiles(Path.Combine(full, ErrorFolder)).Length > 0);
            // An evaluation marks its folder while it writes (its journal, naming the run): a killed one's folder is provably
            // ours once that run has ended, and a live one's is never touched.
            var journal = OperationJournal.Load(full);
            var ownJournal = journal != null && journal.Operation == Operation && WorkingFolders.SamePath(journal.Output, full);
            if (ownJournal && OperationOwner.WhyMayBeRunning(journal.Owner, full) is string running)
                throw Refuse(full, "is being written by another evaluation: " + running + ".", "Wait for it to finish, or pass --out <folder>, a new folder.");
            if (hasAny && !ownJournal && !IsOurs(metrics))
                throw Refuse(full, "holds files named like an evaluation's, but no metrics.json written by " + MetricsJson.Generator + " proves they are.", "Pass --out <folder>, a new folder.");
            // Provably an earlier evaluation (finished, or killed): clear its files so none of them outlives this run.
            var errors = Path.Combine(full, ErrorFolder);
            if (Directory.Exists(errors))
                foreach (var file in Directory.GetFiles(errors, "*" + ErrorSuffix)) FileOps.DeleteFile(file);
            else FileOps.CreateDirectory(errors);
            foreach (var file in Directory.GetFiles(full))
                if (IsOwnName(Path.GetFileName(file)) && Path.GetFileName(file) != OperationJournal.FileName) FileOps.DeleteFile(file);
            MarkRunning(full);
        }

        /// <summary>The journal's operation name for an evaluation's out folder (<see cref="OperationJournal"/>).</summary>
        public const string Operation = "evaluate";

        /// <summary>Marks <paramref name="full"/> as this run's until <see cref="Finish"/>: its journal names this process.</summary>
        static void MarkRunning(string full)
        {
            // Registered before the journal names this process, so that no run here takes it for an ended one.
            OperationOwner.Register(full);
            new OperationJournal { Operation = Operation, Output = full }.Save(full);
        }

        /// <summary>The run is complete (metrics.json written): the folder is no longer marked as being written.</summary>
        public static void Finish(string outFolder)
        {
            OperationJournal.Delete(outFolder);
            OperationOwner.Release(outFolder);
        }

        /// <summary>The names an evaluation writes at the top of its folder: metrics.json, report.html, their temporary files, its journal.</summary>
        static bool IsOwnName(string name) =>
            name == MetricsJson.FileName || name == ReportHtml.FileName || name == OperationJournal.FileName || name == OperationJournal.FileName + ".tmp" ||
            AtomicFile.IsTempName(name, MetricsJson.FileName) || AtomicFile.IsTempName(name, ReportHtml.FileName);

        /// <summary>
        /// After a failed run: deletes the error maps and report it wrote (Prepare had cleared the folder of earlier
        /// evaluations, so every such file is this run's) and, when the run created the folder, the empty folders.
        /// </summary>
        public static void RemoveWritten(string outFolder, bool createdByThisRun)
        {
            var errors = Path.Combine(outFolder, ErrorFolder);
            if (Directory.Exists(errors))
                foreach (var file in Directory.GetFiles(errors, "*" + ErrorSuffix)) FileOps.DeleteFile(file);
            var report = Path.Combine(outFolder, ReportHtml.FileName);
            if (File.Exists(report) && !File.Exists(Path.Combine(outFolder, MetricsJson.FileName))) FileOps.DeleteFile(report);
            Finish(outFolder);
            if (!createdByThisRun) return;
            if (Directory.Exists(errors) && Directory.GetFileSystemEntries(errors).Length == 0) FileOps.DeleteDirectory(errors);
            if (Directory.Exists(outFolder) && Directory.GetFileSystemEntries(outFolder).Length == 0) FileOps.DeleteDirectory(outFolder);
        }

        static bool IsOurs(string metricsPath)
        {
            if (!File.Exists(metricsPath)) return false;
            // Any file that is not an object whose generator is our string is not ours, whatever it holds instead
            // (an object as generator used to end in "unexpected ArgumentException"); a pipe or huge file is not read.
            try { return JToken.Parse(FileOps.ReadText(metricsPath)) is JObject o && o["generator"] is JValue g && g.Type == JTokenType.String && (string)g == MetricsJson.Generator; }
            catch (JsonException) { return false; }
            catch (IOException) { return false; }
            catch (UnauthorizedAccessException) { return false; }
        }

        static InvalidParameterException Refuse(string path, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("--out", path, reason, fix) });
    }
}
