using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes a checked merge: into a hidden sibling of the output folder, renamed into place only when complete;
    /// on failure moved files go back and the partial folder is removed.
    /// </summary>
    static class MergeStaging
    {
        /// <summary>
        /// Builds the dataset in a hidden sibling folder and renames it into place; returns the problem on failure, after
        /// undoing everything. Its journal lists every planned move first, so that a merge killed anywhere is rolled
        /// back (files moved back into the shards) or finished by the next merge into the same output (<see cref="Recovery"/>).
        /// </summary>
        /// <param name="labels">The shards' common labels.json (<see cref="MergeLabels"/>), copied (never moved) with new previews; null for none.</param>
        /// <param name="protocol">The shards' common eval_protocol.json (<see cref="MergeProtocol"/>), copied (never moved); null for none.</param>
        public static ValidationProblem Write(List<ShardFolder> shards, List<MergeFrame> frames, List<MergeTransfer> transfers, string output, bool move, string labels = null,
            string protocol = null)
        {
            var staging = WorkingFolders.NewMerging(output);
            var journal = new OperationJournal { Operation = "merge", Output = output };
            journal.Shards.AddRange(shards.Select(s => s.Folder));
            if (move) journal.Moves.AddRange(transfers.Select(t => new KeyValuePair<string, string>(t.Source, t.Relative)));
            var moved = new List<MergeTransfer>();
            var inPlace = false;
            // This run's until it returns, in the staging folder and then (renamed) in the output: no recovery here touches it.
            OperationOwner.Register(staging);
            OperationOwner.Register(output);
            try
            {
                WorkingFolders.Create(staging, journal); // born with its journal: never an owner-less empty folder
                foreach (var t in transfers)
                {
                    var destination = Path.Combine(staging, t.Relative.Replace('/', Path.DirectorySeparatorChar));
                    FileOps.CreateDirectory(Path.GetDirectoryName(destination));
                    if (move)
                    {
                        FileOps.MoveFile(t.Source, destination);
                        moved.Add(t);
                    }
                    else FileOps.CopyFile(t.Source, destination);
                }
                foreach (var split in ViewCounts.SplitNames)
                {
                    var reference = shards.FirstOrDefault(s => s.Transforms.ContainsKey(split));
                    if (reference == null) continue;
                    // The reference shard's top-level keys as written, the kept frames verbatim where its "frames" stood.
                    var top = reference.Transforms[split];
                    var merged = new JObject();
                    var kept = new JArray(frames.Where(f => f.Split == split).Select(f => f.Frame.Json.DeepClone()));
                    foreach (var property in top.Top.Properties())
                    {
                        if (merged.Count == top.FramesAt) merged["frames"] = kept;
                        merged[property.Name] = property.Value.DeepClone();
                    }
                    if (merged["frames"] == null) merged["frames"] = kept;
                    WriteJson(Path.Combine(staging, ShardMerger.TransformsFileName(split)), merged);
                }
                MergeLabels.Write(labels, staging);
                MergeProtocol.Write(protocol, staging);
                var config = shards.FirstOrDefault(s => s.Config != null);
                if (config != null) FileOps.WriteText(Path.Combine(staging, ShardMerger.ConfigFileName), new DatasetConfig(MergedConfig(config.Config, shards)).ToText());
                journal.State = OperationJournal.Committing;
                journal.Save(staging);
                FileOps.MoveDirectory(staging, output);
                inPlace = true;
                OperationJournal.Delete(output);
                return null;
            }
            catch (Exception e) when (inPlace && (e is IOException || e is UnauthorizedAccessException))
            {
                return null; // merged and in place; the journal left inside is removed by the next run on this output
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                var undone = Undo(moved, staging);
                return new ValidationProblem("output", output, "could not be written: " + e.Message,
                    undone ? "Nothing was changed; fix the cause (disk space, permissions, a folder created meanwhile) and merge again."
                           : "Some moved files could not be put back; they are in " + staging + " under the same relative paths. Merge into the same --out again to move them back.");
            }
            finally
            {
                OperationOwner.Release(staging);
                OperationOwner.Release(output);
            }
        }

        /// <summary>
        /// The first shard's config made to describe the whole dataset: <c>imagesRendered</c> (a boolean, see
        /// <see cref="DatasetConfig.Write"/>) true only when every shard rendered its images, and the per-shard
        /// <c>statistics</c> dropped; the <c>pointCloud</c> record of the shard that wrote points3d.ply.
        /// </summary>
        static JObject MergedConfig(DatasetConfig first, List<ShardFolder> shards)
        {
            var merged = (JObject)first.Json.DeepClone();
            merged.Remove("statistics");
            // Only shard 0 writes points3d.ply (merge carries that file over unchanged), so its record describes the merged dataset.
            var cloud = shards.Select(s => s.Config?.Json[PointCloudRecord.Key]).FirstOrDefault(r => r != null);
            if (cloud != null) merged[PointCloudRecord.Key] = cloud.DeepClone();
            else merged.Remove(PointCloudRecord.Key);
            MergeGeometry.CarryRecord(merged, shards);
            var rendered = shards.Select(s => s.Config?.Json["imagesRendered"]).ToList();
            if (rendered.All(r => r != null && r.Type == JTokenType.Boolean))
                merged["imagesRendered"] = rendered.All(r => (bool)r);
            return merged;
        }

        static bool Undo(List<MergeTransfer> moved, string staging)
        {
            var complete = true;
            for (var i = moved.Count - 1; i >= 0; i--)
            {
                try
                {
                    FileOps.MoveFile(Path.Combine(staging, moved[i].Relative.Replace('/', Path.DirectorySeparatorChar)), moved[i].Source);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    complete = false;
                }
            }
            if (complete && Directory.Exists(staging))
            {
                try { FileOps.DeleteDirectory(staging); }
                catch (IOException) { }
                catch (UnauthorizedAccessException) { }
            }
            return complete;
        }

        static void WriteJson(string path, JToken json) => FileOps.WriteText(path, json.ToString(Formatting.Indented) + "\n");
    }
}
