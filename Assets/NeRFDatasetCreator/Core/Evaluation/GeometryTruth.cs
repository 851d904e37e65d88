using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which ground-truth mesh <c>--geometry</c> compares against and which train views decide what was observed. A
    /// static dataset has one mesh and every train view. A dynamic dataset (a <c>time</c> record or per-frame <c>time</c>
    /// keys) has a surface per time step, so the mesh and the views must be of one step k: the step's pack file
    /// (<c>geometry/target_mesh_t&lt;k&gt;.ply</c>, or the start-time pack for k = 0) and the train views whose
    /// <c>time_step</c> is k (D-NeRF's monocular layout: the one train view of that step; multi-view: every camera).
    /// Ambiguity is refused, naming <c>--step</c>: a per-step pack without <c>--step</c>, a step the pack lacks, a
    /// <c>--gt-mesh</c> on a dynamic dataset without <c>--step</c>, <c>--step</c> on a static dataset.
    /// </summary>
    public sealed class GeometryTruth
    {
        public string Path { get; private set; }
        public string Source { get; private set; }

        /// <summary>The time step compared, or null for a static dataset.</summary>
        public int? Step { get; private set; }

        /// <summary>That step's normalised time (the views' <c>time</c> key), when known.</summary>
        public double? Time { get; private set; }

        /// <summary>The train split (its intrinsics and depth scale).</summary>
        public EvaluationDataset Train { get; private set; }

        /// <summary>The train views whose depth maps decide what was observed.</summary>
        public IReadOnlyList<EvaluationFrame> TrainFrames { get; private set; }

        public bool TrainHasDepth => TrainFrames.Count > 0 && TrainFrames.All(f => f.DepthPath != null);

        /// <summary>Whether the dataset is a dynamic capture's: a <c>time</c> record in dataset_config.json, or per-frame times.</summary>
        public static bool IsDynamic(EvaluationDataset dataset, EvaluationDataset train) =>
            dataset.Config?.Time != null || dataset.Frames.Any(f => f.Time.HasValue) || train.Frames.Any(f => f.Time.HasValue);

        public static GeometryTruth Resolve(EvaluationDataset dataset, string reconstructionPath, string truthMeshPath, int? step)
        {
            var train = EvaluationDataset.Read(dataset.Root, "train");
            var entries = dataset.Config?.GeometryEntries ?? Array.Empty<GeometryPackEntry>();
            var malformed = entries.FirstOrDefault(e => e.Problem != null);
            if (malformed != null && truthMeshPath == null)
                throw Refuse(DatasetLayout.ConfigFileName, System.IO.Path.Combine(dataset.Root, DatasetLayout.ConfigFileName), malformed.Problem, "Capture again, or correct the record; or pass the mesh with --gt-mesh.");
            if (!IsDynamic(dataset, train))
            {
                if (step.HasValue)
                    throw Refuse("--step", step.Value.ToString(System.Globalization.CultureInfo.InvariantCulture), "picks a time step, but " + dataset.Root + " is a static capture (no time record, no per-frame time).", "Leave --step out.");
                string staticNote = null;
                var (path, source) = truthMeshPath != null ? (System.IO.Path.GetFullPath(truthMeshPath), "--gt-mesh") : PackFile(dataset, reconstructionPath, entries.FirstOrDefault(), out staticNote);
                return new GeometryTruth { Path = path, Source = source, Train = train, TrainFrames = train.Frames, Note = staticNote };
            }

            var perStep = dataset.Config?.GeometryIsPerStep == true;
            var known = entries.Where(e => e.Step.HasValue).Select(e => e.Step.Value).ToList();
            int k;
            GeometryPackEntry entry = null;
            if (truthMeshPath != null)
            {
                if (!step.HasValue)
                    throw Refuse("--step", "(missing)", "is needed with --gt-mesh on a dynamic dataset: the mesh is the surface at one time step, and only that step's train views may decide what was observed.",
                        "Add --step <k>, the time_step of the train views the mesh belongs to.");
                k = step.Value;
            }
            else if (perStep)
            {
                if (!step.HasValue)
                    throw Refuse("--step", "(missing)", "is needed: the geometry pack holds one mesh per time step (" + StepList(entries) + "), so which one the reconstruction is of is ambiguous.",
                        "Add --step <k> for one reconstruction, or pass a folder of per-step reconstructions (mesh_0000.ply …, the step number last in each name) as --geometry.");
                k = step.Value;
                entry = entries.FirstOrDefault(e => e.Step == k);
                if (entry == null)
                    throw Refuse("--step", k.ToString(System.Globalization.CultureInfo.InvariantCulture), "is not a step of the geometry pack (" + StepList(entries) + ").", "Pick one of those steps.");
            }
            else
            {
                // The start-time pack (this round's record says step 0; last round's did not, and wrote the start too).
                k = step ?? 0;
                if (k != 0)
                    throw Refuse("--step", k.ToString(System.Globalization.CultureInfo.InvariantCulture),
                        "asks for a time step the geometry pack does not hold: it has the target at the start time only (step 0).",
                        "Capture again with \"geometryPack\": \"everyStep\" for a mesh per step, or pass step " + k + "'s mesh with --gt-mesh.");
                entry = entries.FirstOrDefault();
            }
            // Multi-view frames carry time_step; monocular ones only their time (train view i is at step i), so a frame
            // without time_step belongs to step k when its time is step k's: the pack's record, else k/(steps − 1).
            var time = entry?.Time ?? StepTime(dataset.Config, k);
            var frames = train.Frames.Where(f => f.TimeStep == k || f.TimeStep == null && time.HasValue && f.Time.HasValue && Math.Abs(f.Time.Value - time.Value) < 1e-9).ToList();
            if (frames.Count == 0)
                throw Refuse("--step", k.ToString(System.Globalization.CultureInfo.InvariantCulture), "matches no train view (no frame of transforms_train.json has time_step " + k +
                    (time.HasValue ? " or time " + time.Value.ToString("0.######", System.Globalization.CultureInfo.InvariantCulture) : "") + ").",
                    "Pick a step the train split holds" + (known.Count > 0 ? " (" + StepList(entries) + ")" : "") + ".");
            string note = null;
            var (truth, from) = truthMeshPath != null ? (System.IO.Path.GetFullPath(truthMeshPath), "--gt-mesh") : PackFile(dataset, reconstructionPath, entry, out note);
            return new GeometryTruth { Path = truth, Source = from + ", time step " + k, Step = k, Time = time ?? frames[0].Time, Train = train, TrainFrames = frames, Note = note };
        }

        /// <summary>Step k's normalised time from dataset_config.json's time record (k/(steps − 1)), or null when there is none.</summary>
        static double? StepTime(DatasetConfig config, int k)
        {
            var steps = config?.Time?.Steps;
            if (steps == null || steps.Value < 2 || k >= steps.Value) return null;
            return k / (double)(steps.Value - 1);
        }

        /// <summary>
        /// The pack file of <paramref name="entry"/>; refuses when it is missing. Without a record: in this plugin's dataset
        /// (a dataset_config.json) an unrecorded <c>geometry/target_mesh.ply</c> is refused — a leftover of another capture
        /// would score the reconstruction against the wrong surface, and <c>validate</c> warns that evaluate does not use it;
        /// in another tool's dataset (no dataset_config.json) the conventional file is used, and <paramref name="note"/> says so.
        /// </summary>
        static (string, string) PackFile(EvaluationDataset dataset, string reconstructionPath, GeometryPackEntry entry, out string note)
        {
            note = null;
            var relative = entry?.File ?? TargetMeshPly.RelativePath;
            var path = PathSafety.Inside(dataset.Root, relative, out _);
            if (path == null || !File.Exists(path))
                throw Refuse("--geometry", reconstructionPath ?? "", "needs the ground-truth mesh, and " + System.IO.Path.Combine(dataset.Root, relative) + " does not exist (the dataset has no geometry pack).",
                    "Pass the target's mesh in the dataset's output frame and units with --gt-mesh <file.ply|.obj>.");
            if (entry != null) return (path, "the geometry pack recorded in dataset_config.json (" + relative + ")");
            if (dataset.Config != null)
                throw Refuse("--geometry", reconstructionPath ?? "", "needs the ground-truth mesh, and " + path + " is not recorded in " + DatasetLayout.ConfigFileName +
                                                                    "'s geometry, so it is not taken for this capture's target (a leftover of another capture?).",
                    "If it is this capture's target in the output frame, pass it explicitly: --gt-mesh " + path + "; or capture again with the geometry pack on.");
            note = "--geometry is scored against " + relative + ", found by its conventional name: the dataset has no " + DatasetLayout.ConfigFileName +
                   " to record it. Pass --gt-mesh to name the ground truth yourself.";
            return (path, "the geometry pack " + relative + ", by its conventional name (no " + DatasetLayout.ConfigFileName + " records it)");
        }

        /// <summary>Set when the ground truth was found by its conventional name only (<see cref="PackFile"/>): evaluate prints it as a note.</summary>
        public string Note { get; private set; }

        static string StepList(IReadOnlyList<GeometryPackEntry> entries)
        {
            var steps = entries.Where(e => e.Step.HasValue).ToList();
            if (steps.Count == 0) return "no steps";
            string Show(GeometryPackEntry e) => "step " + e.Step.Value + (e.Time.HasValue ? " = time " + e.Time.Value.ToString("0.####", System.Globalization.CultureInfo.InvariantCulture) : "");
            return steps.Count == 1 ? Show(steps[0]) : Show(steps[0]) + " … " + Show(steps[steps.Count - 1]);
        }

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
