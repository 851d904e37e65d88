using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Merge keeps the shards' <c>eval_protocol.json</c> (<see cref="EvalProtocolFile"/>): every shard of one capture
    /// writes the same file, so it is copied (never moved) from the first; a shard without one, or with another text,
    /// stops the merge — the merged dataset would otherwise carry a protocol one shard contradicts.
    /// </summary>
    static class MergeProtocol
    {
        /// <summary>The protocol file to copy into the merged dataset, or null when no shard has one.</summary>
        public static string Check(IReadOnlyList<ShardFolder> shards, List<ValidationProblem> problems)
        {
            var files = shards.Select(s => Path.Combine(s.Folder, EvalProtocolFile.FileName)).ToList();
            var first = files.FirstOrDefault(File.Exists);
            if (first == null) return null;
            var text = FileOps.ReadText(first);
            foreach (var file in files)
            {
                if (!File.Exists(file))
                    problems.Add(new ValidationProblem(file, "(missing)", "is missing while " + first + " exists.", "Rerun this shard, or copy the protocol from another shard of the same capture."));
                else if (FileOps.ReadText(file) != text)
                    problems.Add(new ValidationProblem(file, "(differs)", "is not the same protocol as " + first + ": the shards were captured with different backgrounds or plugin versions.",
                        "Rerun this shard with the same settings as the others."));
            }
            return first;
        }

        public static void Write(string protocol, string staging)
        {
            if (protocol != null) FileOps.CopyFile(protocol, Path.Combine(staging, EvalProtocolFile.FileName));
        }
    }
}
