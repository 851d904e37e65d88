using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The geometry pack in a merge. Shard 0 writes it (<see cref="DatasetRun.WritesGeometryPack"/>), so exactly one
    /// shard's dataset_config.json records it; merge carries the files that record names over unchanged, after checking
    /// that each exists, is no link and still has its recorded SHA-256, and that a per-step pack lists every step of the
    /// config's <c>time.steps</c> once. Two shards recording different packs are a problem, never a silent pick; a file in
    /// a shard's <c>geometry/</c> that no record names stays behind with a warning.
    /// </summary>
    static class MergeGeometry
    {
        /// <summary>The shard whose record describes the merged dataset (null when none has one).</summary>
        public static ShardFolder Owner(IEnumerable<ShardFolder> shards) =>
            shards.FirstOrDefault(s => s.Config?.GeometryRecord != null);

        /// <summary>
        /// The merged dataset_config.json's geometry record: the owner's (shard 0's, carried over unchanged with its
        /// files), or none.
        /// </summary>
        public static void CarryRecord(JObject merged, IEnumerable<ShardFolder> shards)
        {
            var pack = Owner(shards)?.Config.GeometryRecord;
            if (pack != null) merged[GeometryPackRecord.Key] = pack.DeepClone();
            else merged.Remove(GeometryPackRecord.Key);
        }

        /// <param name="add">Adds a transfer: source path, path relative to the merged dataset, owner's name.</param>
        /// <param name="claim">Marks a shard entry (the geometry folder) as handled, so it is not reported as an extra.</param>
        public static void Plan(List<ShardFolder> shards, Action<string, string, string> add, Action<string> claim,
            List<ValidationProblem> problems, List<string> warnings)
        {
            var owner = Owner(shards);
            if (owner != null)
            {
                var record = owner.Config.GeometryRecord;
                foreach (var other in shards.Where(s => s != owner && s.Config?.GeometryRecord != null))
                    if (!JToken.DeepEquals(record, other.Config.GeometryRecord))
                        problems.Add(new ValidationProblem(Path.Combine(other.Folder, DatasetLayout.ConfigFileName) + ": " + GeometryPackRecord.Key, "(a second geometry pack)",
                            "differs from the one " + owner.Name + " recorded; only shard 0 writes the geometry pack.", "Rerun this shard with the job's config and the shard argument it was given."));
                CheckSteps(owner, problems);
                foreach (var entry in owner.Config.GeometryEntries)
                {
                    var where = Path.Combine(owner.Folder, DatasetLayout.ConfigFileName) + ": geometry " + entry.File;
                    var name = Path.GetFileName(entry.File);
                    if (entry.File != TargetMeshPly.Folder + "/" + name || !GeometryPackSteps.IsPackFile(name))
                    {
                        problems.Add(new ValidationProblem(where, entry.File, "is not a geometry pack file name (geometry/target_mesh.ply or geometry/target_mesh_t<step>.ply).", "Rerun " + owner.Name + "."));
                        continue;
                    }
                    var source = Path.Combine(owner.Folder, TargetMeshPly.Folder, name);
                    if (!File.Exists(source))
                        problems.Add(new ValidationProblem(where, entry.File, "names " + source + ", which does not exist.", "Rerun " + owner.Name + "; its capture did not finish."));
                    else if (PathSafety.IsLink(source))
                        problems.Add(new ValidationProblem(source, "(symbolic link)", "is a link, which may lead outside " + owner.Name + "; merge never follows links.", "Replace the link by the file it points to, then merge again."));
                    else if (entry.Sha256 != null && PointCloudRecord.HashOf(source) != entry.Sha256)
                        problems.Add(new ValidationProblem(source, "(changed)", "no longer has the SHA-256 its dataset_config.json records, so the mesh is not the one captured.", "Rerun " + owner.Name + " to write the geometry pack again."));
                    else add(source, TargetMeshPly.Folder + "/" + name, owner.Name);
                }
            }
            foreach (var shard in shards)
            {
                var folder = Path.Combine(shard.Folder, TargetMeshPly.Folder);
                if (!Directory.Exists(folder) || PathSafety.IsLink(folder)) continue;
                claim(folder);
                var named = shard == owner
                    ? new HashSet<string>(shard.Config.GeometryEntries.Select(e => Path.GetFileName(e.File)), StringComparer.Ordinal)
                    : new HashSet<string>();
                foreach (var entry in Directory.EnumerateFileSystemEntries(folder).OrderBy(p => p, StringComparer.Ordinal))
                    if (!named.Contains(Path.GetFileName(entry)))
                        warnings.Add(entry + " is named by no geometry record of its shard's " + DatasetLayout.ConfigFileName + " and was not merged.");
            }
        }

        /// <summary>A per-step pack holds steps 0 … time.steps − 1, each once, in order.</summary>
        static void CheckSteps(ShardFolder owner, List<ValidationProblem> problems)
        {
            var config = owner.Config;
            if (!config.GeometryIsPerStep) return;
            var steps = config.GeometryEntries.Select(e => e.Step ?? -1).ToList();
            var expected = config.Time?.Steps ?? -1;
            if (expected < 0 || !steps.SequenceEqual(Enumerable.Range(0, expected)))
                problems.Add(new ValidationProblem(Path.Combine(owner.Folder, DatasetLayout.ConfigFileName) + ": geometry.steps", steps.Count + " entries",
                    "do not list each time step 0 … " + (expected - 1) + " once (time.steps is " + (expected < 0 ? "missing" : expected.ToString(System.Globalization.CultureInfo.InvariantCulture)) + ").",
                    "Rerun " + owner.Name + "; its geometry pack is incomplete."));
        }
    }
}
