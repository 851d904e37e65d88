using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>--geometry &lt;folder&gt;</c> on a dynamic dataset with a per-step geometry pack: one reconstruction per time
    /// step, as 4D surface methods export them (one mesh per frame, scored per frame and averaged over frames). Each
    /// <c>.ply</c> / <c>.obj</c> in the folder (not its subfolders) belongs to the step number last in its name
    /// (<c>mesh_0003.ply</c>, <c>frame3.obj</c>, <c>target_mesh_t0003.ply</c> are step 3); each is compared with that
    /// step's ground-truth mesh, observed points decided by that step's train views (<see cref="GeometryTruth"/>). Every
    /// file is matched before anything is computed: a name without a number, two files of one step, a step the pack lacks
    /// are refused. Steps without a file are listed, not guessed.
    /// </summary>
    public static class GeometryStepsEvaluation
    {
        static readonly Regex LastNumber = new Regex(@"(\d+)(?!.*\d)", RegexOptions.CultureInvariant);

        /// <summary>Each reconstruction with its resolved ground truth, in step order; refuses as the summary says.</summary>
        public static IReadOnlyList<KeyValuePair<string, GeometryTruth>> Match(EvaluationDataset dataset, string folder)
        {
            if (dataset.Config?.GeometryIsPerStep != true)
                throw Refuse(folder, "is a folder of per-step reconstructions, but " + dataset.Root + " has no per-step geometry pack (dataset_config.json's geometry lists no steps).",
                    "Capture with \"geometryPack\": \"everyStep\", or pass one reconstruction file (with --step on a dynamic dataset).");
            var files = Directory.EnumerateFiles(folder)
                .Where(f => f.EndsWith(".ply", StringComparison.OrdinalIgnoreCase) || f.EndsWith(".obj", StringComparison.OrdinalIgnoreCase))
                .OrderBy(f => f, StringComparer.Ordinal).ToList();
            if (files.Count == 0)
                throw Refuse(folder, "holds no .ply or .obj file.", "Put one reconstruction per time step in it, the step number last in each name (mesh_0000.ply …).");
            var byStep = new SortedDictionary<int, string>();
            foreach (var file in files)
            {
                var match = LastNumber.Match(Path.GetFileNameWithoutExtension(file));
                if (!match.Success || !int.TryParse(match.Value, NumberStyles.None, CultureInfo.InvariantCulture, out var step))
                    throw Refuse(file, "has no step number in its name.", "Name each reconstruction with its time step last (mesh_0003.ply for step 3), or move other files out of the folder.");
                if (byStep.TryGetValue(step, out var other))
                    throw Refuse(file, "is step " + step + ", as " + Path.GetFileName(other) + " is.", "Keep one reconstruction per time step in the folder.");
                byStep[step] = file;
            }
            var result = new List<KeyValuePair<string, GeometryTruth>>();
            foreach (var pair in byStep)
            {
                GeometryTruth truth;
                try { truth = GeometryTruth.Resolve(dataset, pair.Value, null, pair.Key); }
                catch (InvalidParameterException e)
                {
                    throw new InvalidParameterException(e.Problems.Select(p => new ValidationProblem("--geometry", pair.Value, "(step " + pair.Key + " by its name): " + p.Field + " " + p.Reason, p.Fix)).ToList());
                }
                result.Add(new KeyValuePair<string, GeometryTruth>(pair.Value, truth));
            }
            return result;
        }

        /// <summary>The steps of the pack without a reconstruction in the folder.</summary>
        public static IReadOnlyList<int> Missing(EvaluationDataset dataset, IReadOnlyList<KeyValuePair<string, GeometryTruth>> matched)
        {
            var have = new HashSet<int>(matched.Select(m => m.Value.Step ?? -1));
            return (dataset.Config?.GeometryEntries ?? Array.Empty<GeometryPackEntry>()).Where(e => e.Step.HasValue && !have.Contains(e.Step.Value)).Select(e => e.Step.Value).ToList();
        }

        public static List<GeometryResult> Run(IReadOnlyList<KeyValuePair<string, GeometryTruth>> matched, double? threshold, int truthPoints, Action<string> progress)
        {
            var results = new List<GeometryResult>();
            foreach (var pair in matched)
            {
                progress?.Invoke("geometry: time step " + pair.Value.Step + " (" + Path.GetFileName(pair.Key) + ")");
                results.Add(GeometryEvaluation.Run(pair.Value, pair.Key, threshold, truthPoints, progress));
            }
            return results;
        }

        static InvalidParameterException Refuse(string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("--geometry", value, reason, fix) });
    }
}
