using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Merge's part for labelled captures: every shard's labels.json must give every id the same object and class
    /// (ids are derived from the scene's hierarchy, so shards of one unchanged scene agree; a shard captured from an
    /// edited scene would not, and its maps' ids would then mean other objects). The merged dataset gets the shared
    /// labels.json and new previews of its whole splits.
    /// </summary>
    static class MergeLabels
    {
        /// <summary>Copies the shards' common labels.json (<see cref="Check"/>'s; never moved) into the merged dataset with new previews of its whole splits; nothing for null.</summary>
        public static void Write(string labels, string staging)
        {
            if (labels == null) return;
            FileOps.CopyFile(labels, Path.Combine(staging, DatasetLayout.LabelsFileName));
            LabelFiles.WritePreviews(staging);
        }

        /// <summary>The labels.json to carry over (the first shard's), or null when no shard has one; disagreements are problems.</summary>
        public static string Check(List<ShardFolder> shards, List<ValidationProblem> problems)
        {
            var withLabels = shards.Where(s => File.Exists(Path.Combine(s.Folder, DatasetLayout.LabelsFileName))).ToList();
            if (withLabels.Count == 0) return null;
            foreach (var s in shards.Except(withLabels))
                problems.Add(new ValidationProblem(Path.Combine(s.Folder, DatasetLayout.LabelsFileName), "(missing)",
                    "is missing while " + withLabels[0].Name + " has one; every shard of a labelled capture writes it.",
                    "Rerun this shard with the same config (its \"labels\" section), then merge again."));
            LabelTable reference = null;
            ShardFolder referenceShard = null;
            foreach (var shard in withLabels)
            {
                var path = Path.Combine(shard.Folder, DatasetLayout.LabelsFileName);
                LabelTable table;
                try
                {
                    table = LabelsJson.ReadFile(path);
                }
                catch (InvalidParameterException e)
                {
                    problems.AddRange(e.Problems);
                    continue;
                }
                if (reference == null)
                {
                    reference = table;
                    referenceShard = shard;
                    continue;
                }
                var difference = LabelsJson.Difference(reference, table);
                if (difference != null)
                    problems.Add(new ValidationProblem(path, "(differs)",
                        "does not agree with " + referenceShard.Name + "'s labels.json: " + difference + ". The same id would name different objects in the merged dataset.",
                        "Capture every shard from the same, unchanged scene with the same \"labels\" settings, then merge again."));
            }
            return referenceShard == null ? null : Path.Combine(referenceShard.Folder, DatasetLayout.LabelsFileName);
        }
    }
}
