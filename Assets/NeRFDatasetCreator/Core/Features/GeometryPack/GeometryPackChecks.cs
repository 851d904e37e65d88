using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>validate</c>'s look at the geometry pack: every mesh dataset_config.json records (<see cref="GeometryPackStepRecord.Entries"/>)
    /// lies inside the dataset, exists and still has its recorded SHA-256 (problems); a pack file in <c>geometry/</c> that
    /// no record names is a warning (a leftover of another capture, which evaluate would not use).
    /// </summary>
    public static class GeometryPackChecks
    {
        /// <param name="config">The dataset's <c>dataset_config.json</c>, read once by the validator.</param>
        public static void Check(string folder, DatasetConfigFile config, bool skipFiles, DatasetValidationReport report)
        {
            // No config, or one that cannot be read (reported by the validator's own config check) or is not JSON: nothing to check.
            if (config.State == DatasetConfigState.Missing || config.State == DatasetConfigState.Unreadable || config.State == DatasetConfigState.NotJson) return;
            var entries = config.Config?.GeometryEntries ?? Array.Empty<GeometryPackEntry>();
            var recorded = new HashSet<string>(StringComparer.Ordinal);
            foreach (var entry in entries)
                if (entry.Problem != null)
                    report.Problems.Add(DatasetProblem.Structure(DatasetLayout.ConfigFileName, -1, null, entry.Problem + " Capture again, or correct the record."));
            if (!skipFiles)
                foreach (var entry in entries)
                {
                    var inside = PathSafety.Inside(folder, entry.File, out _);
                    if (inside == null)
                    {
                        report.Problems.Add(DatasetProblem.Structure(DatasetLayout.ConfigFileName, -1, null, "geometry names " + entry.File + ", which is outside the dataset."));
                        continue;
                    }
                    recorded.Add(Path.GetFullPath(inside));
                    if (!File.Exists(inside))
                        report.Problems.Add(DatasetProblem.Structure(entry.File, -1, null, "is recorded as the geometry pack" + StepText(entry) + " in " + DatasetLayout.ConfigFileName + " but does not exist (capture again, or remove the record)."));
                    else if (entry.Sha256 != null && PointCloudRecord.HashOf(inside) != entry.Sha256)
                        report.Problems.Add(DatasetProblem.Structure(entry.File, -1, null, "does not have the SHA-256 " + DatasetLayout.ConfigFileName + " records for it: the mesh" + StepText(entry) + " changed after the capture."));
                }
            var pack = Path.Combine(folder, TargetMeshPly.Folder);
            if (skipFiles || !Directory.Exists(pack)) return;
            foreach (var file in Directory.EnumerateFiles(pack).OrderBy(f => f, StringComparer.Ordinal))
                if (GeometryPackSteps.IsPackFile(Path.GetFileName(file)) && !recorded.Contains(Path.GetFullPath(file)))
                    report.Warnings.Add(DatasetProblem.Structure(TargetMeshPly.Folder + "/" + Path.GetFileName(file), -1, null,
                        "is not recorded in " + DatasetLayout.ConfigFileName + "'s geometry, so evaluate will not use it (a leftover of another capture?)."));
        }

        static string StepText(GeometryPackEntry entry) => entry.Step.HasValue ? " of time step " + entry.Step.Value : "";
    }
}
