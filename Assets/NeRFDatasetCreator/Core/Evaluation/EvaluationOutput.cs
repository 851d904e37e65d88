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
    /// holds only those and whose metrics.json this tool wrote. Any other file there — or a folder inside the dataset —
    /// is refused before anything is written.
    /// </summary>
    public static class EvaluationOutput
    {
        public const string ErrorFolder = "errors";
        public const string ErrorSuffix = "_error.png";

        public static void Prepare(string outFolder, string datasetRoot)
        {
            var full = Path.GetFullPath(outFolder);
            var dataset = Path.GetFullPath(datasetRoot).TrimEnd(Path.DirectorySeparatorChar) + Path.DirectorySeparatorChar;
            if ((full + Path.DirectorySeparatorChar).StartsWith(dataset, StringComparison.Ordinal))
                throw Refuse(full, "is inside the dataset; evaluation never adds files to a dataset.", "Pass --out <folder> outside the dataset.");
            if (File.Exists(full)) throw Refuse(full, "is a file.", "Pass --out <folder>, a folder that does not exist yet or an earlier evaluation's.");
            if (!Directory.Exists(full))
            {
                FileOps.CreateDirectory(full);
                FileOps.CreateDirectory(Path.Combine(full, ErrorFolder));
                return;
            }
            var strangers = new List<string>();
            foreach (var entry in Directory.GetFileSystemEntries(full))
            {
                var name = Path.GetFileName(entry);
                if (File.Exists(entry) && (name == MetricsJson.FileName || name == ReportHtml.FileName)) continue;
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
            if (hasAny && !IsOurs(metrics))
                throw Refuse(full, "holds files named like an evaluation's, but no metrics.json written by " + MetricsJson.Generator + " proves they are.", "Pass --out <folder>, a new folder.");
            // Provably an earlier evaluation: clear its files so none of them outlives this run.
            var errors = Path.Combine(full, ErrorFolder);
            if (Directory.Exists(errors))
                foreach (var file in Directory.GetFiles(errors, "*" + ErrorSuffix)) FileOps.DeleteFile(file);
            else FileOps.CreateDirectory(errors);
            if (File.Exists(Path.Combine(full, ReportHtml.FileName))) FileOps.DeleteFile(Path.Combine(full, ReportHtml.FileName));
            if (File.Exists(metrics)) FileOps.DeleteFile(metrics);
        }

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
