using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The engine-free half of a capture run. <see cref="Prepare"/> checks everything that can be checked before
    /// rendering and fixes what will be rendered (a shard's share of the plan) and where it goes;
    /// <see cref="Begin"/> opens the write session; after the images, <see cref="Finish"/> writes the JSON files
    /// (last, so they never name a missing image), the shard manifest, and moves the dataset into place.
    /// </summary>
    public sealed class DatasetRun
    {
        DatasetRun(CapturePlan fullPlan, CapturePlan plan, ShardSpec shard, string datasetFolder, string projectRoot,
            IReadOnlyList<ValidationProblem> problems)
        {
            FullPlan = fullPlan;
            Plan = plan;
            Shard = shard;
            DatasetFolder = datasetFolder;
            ProjectRoot = projectRoot;
            Problems = problems;
        }

        /// <summary>Every reason the run cannot start; empty when it can.</summary>
        public IReadOnlyList<ValidationProblem> Problems { get; }

        public bool IsValid => Problems.Count == 0;

        /// <summary>The views this run renders and writes: the whole plan, or a shard's share of it. Null when invalid.</summary>
        public CapturePlan Plan { get; }

        /// <summary>The plan of the whole dataset (all shards).</summary>
        public CapturePlan FullPlan { get; }

        public ShardSpec Shard { get; }

        /// <summary>The absolute folder the finished dataset is moved to.</summary>
        public string DatasetFolder { get; }

        public string ProjectRoot { get; }

        /// <param name="datasetFolder">The dataset folder itself (batch mode's -nerfOut); null for the settings' output folder and name.</param>
        public static DatasetRun Prepare(DatasetSettings settings, PlanTarget target, string projectRoot,
            ShardSpec shard = default, string datasetFolder = null)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var whole = shard.Count == 0 ? ShardSpec.Whole : shard;
            var folder = string.IsNullOrWhiteSpace(datasetFolder)
                ? SafeOutput.ResolveOutputFolder(settings, projectRoot)
                : System.IO.Path.GetFullPath(System.IO.Path.Combine(projectRoot ?? "", datasetFolder));

            var problems = new List<ValidationProblem>(CapturePlan.Check(settings, target));
            problems.AddRange(SafeOutput.CheckOutputFolder(folder, projectRoot, settings.Overwrite));
            problems = problems.GroupBy(p => p.ToString()).Select(g => g.First()).ToList();
            if (problems.Count > 0) return new DatasetRun(null, null, whole, folder, projectRoot, problems);

            var full = CapturePlan.Build(settings, target);
            var counts = CountsOf(full);
            var plan = whole.Count == 1
                ? full
                : full.Only(v => ShardAssignment.Contains(whole, counts, DatasetSplits.Name(v.Split), v.Index));
            return new DatasetRun(full, plan, whole, folder, projectRoot, problems);
        }

        /// <summary>Checks the output folder again (it may have changed since <see cref="Prepare"/>) and creates the working folder.</summary>
        public DatasetWriteSession Begin()
        {
            if (!IsValid) throw new InvalidParameterException(Problems);
            return DatasetWriteSession.Begin(DatasetFolder, FullPlan.Settings.Overwrite, ProjectRoot);
        }

        /// <summary>
        /// Whether this run writes <c>points3d.ply</c>: the settings ask for points and this is the whole dataset or
        /// shard 0 (one cloud per dataset; merge carries it over).
        /// </summary>
        public bool WritesPointCloud => IsValid && FullPlan.Settings.PointCloudPoints > 0 && Shard.Index == 0;

        /// <summary>
        /// Whether this run writes the geometry pack (<c>geometry/target_mesh.ply</c>, <see cref="TargetMeshPly"/>, or one
        /// mesh per time step with <c>"geometryPack": "everyStep"</c>, <see cref="GeometryPackSteps"/>): the whole dataset
        /// or shard 0 (one pack per dataset; merge carries it over, as points3d.ply), and only while the settings'
        /// <c>geometryPack</c> is on.
        /// </summary>
        public bool WritesGeometryPack => IsValid && Shard.Index == 0 && FullPlan.Settings.GeometryPack;

        /// <summary>
        /// Whether <see cref="Finish"/> computes <c>flow/</c> (the settings' <c>flow</c> section, Documentation~/flow.md) after
        /// the geometry pack: a whole dataset only, since a shard holds only its share of each video (after merge,
        /// <c>nerf-dataset flow</c> adds it).
        /// </summary>
        public bool WritesFlow => WritesGeometryPack && Shard.Count == 1 && FullPlan.Settings.GeometryPackEveryStep
            && FullPlan.Settings.Flow != null && FullPlan.Settings.Flow.Enabled;

        /// <summary>The threads flow is computed on (<see cref="FlowWriter.Write"/>): every core by default.</summary>
        public int FlowThreads { get; set; } = Math.Max(1, Environment.ProcessorCount);

        /// <summary>After <see cref="Finish"/>: the capture summary's sentence about flow/ (<see cref="FlowConfigRecord.Summary"/>), or null without flow.</summary>
        public string FlowSummary { get; private set; }

        /// <summary>
        /// Writes <c>points3d.ply</c> when <paramref name="pointCloud"/> has points (output world, e.g. from
        /// <see cref="TargetPointCloud.Sample"/>; its SHA-256 goes into dataset_config.json's <c>pointCloud</c> record), the
        /// transforms files, dataset_config.json, <c>rig_preview.png</c> (<see cref="RigPreviewPicture"/>: the only picture
        /// of an inside-out volume's box, since <c>nerf-dataset plan</c> cannot read a scene; a whole dataset only, as
        /// merge carries no per-shard extras) and, for a shard, shard.json; then commits. With
        /// <paramref name="targetMeshes"/> (the target's meshes in the Unity world, as collected for the point cloud) and
        /// <see cref="WritesGeometryPack"/>, also the geometry pack <c>geometry/target_mesh.ply</c> in the output frame,
        /// recorded under <c>geometry</c> in dataset_config.json (<see cref="GeometryPackRecord"/>); with
        /// <paramref name="targetMeshesAtStep"/> (the target posed at step k, Unity world) and a dynamic capture asking for
        /// every step, one mesh per step instead (<see cref="GeometryPackWriter"/>).
        /// </summary>
        /// <param name="labels">
        /// The capture's label table when its settings write id maps (<c>labels</c>): writes <c>labels.json</c> and the
        /// splits' previews (<see cref="LabelFiles"/>). Every shard writes the whole table; merge checks they agree.
        /// </param>
        /// <param name="environments">Relighting's environment maps by condition name, in the output world (<see cref="LightsFile"/>); needed when the settings relight with an environment.</param>
        /// <param name="geometryProgress">(steps done, steps) while the per-step geometry pack is written (<see cref="GeometryPackWriter.Write"/>); may be null.</param>
        /// <param name="flowProgress">(pairs and query frames done, all of them) while flow is computed (<see cref="WritesFlow"/>); may be null.</param>
        public void Finish(DatasetWriteSession session, Provenance provenance, IReadOnlyList<CloudPoint> pointCloud = null,
            IReadOnlyList<SurfaceMesh> targetMeshes = null, LabelTable labels = null, Func<int, IReadOnlyList<SurfaceMesh>> targetMeshesAtStep = null,
            Action<int, int> geometryProgress = null, Action<int, int> flowProgress = null, IReadOnlyDictionary<string, EnvironmentMap> environments = null)
        {
            if (FullPlan.Settings.Labels != null && FullPlan.Settings.Labels.Enabled)
            {
                if (labels == null) throw new InvalidOperationException("This capture writes instance/semantic maps; pass its label table to Finish so labels.json is written.");
                LabelFiles.Write(session, Plan, labels);
            }
            // Relighting: lights/lights.json and each environment's equirect (every shard writes them, as labels.json).
            LightsFile.Write(session, FullPlan.Settings, environments);
            var geometry = WritesGeometryPack ? GeometryPackWriter.Write(session, Plan, targetMeshes, targetMeshesAtStep, geometryProgress) : null;
            PointCloudRecord record = null;
            if (pointCloud != null && pointCloud.Count > 0)
            {
                var path = session.PathOf(TargetPointCloud.FileName);
                PlyWriter.Write(path, pointCloud);
                record = PointCloudRecord.Of(path, TargetPointCloud.FileName, pointCloud.Count);
            }
            DatasetMetadataFiles.Write(session, Plan, provenance, record, geometry, wholeDataset: Shard.Count == 1);
            FlowSummary = null;
            if (WritesFlow)
            {
                // Flow reads what was just written (the transforms, the per-step geometry pack and its record), so it
                // comes after them; dataset_config.json is then written again with its flow record. Both are this run's
                // files in its own working folder, before anything is moved into place.
                var flow = FlowWriter.Write(session.WorkingFolder, FullPlan.Settings.Flow, flowProgress, FlowThreads);
                session.WriteText(DatasetLayout.ConfigFileName, DatasetConfig.Write(Plan, provenance, record, geometry, FlowConfigRecord.Of(flow)));
                FlowSummary = FlowConfigRecord.Summary(flow);
            }
            else if (IsValid && FullPlan.Settings.Flow != null && FullPlan.Settings.Flow.Enabled && Shard.Count > 1)
                FlowSummary = "No flow/ in a shard: run nerf-dataset flow on the merged dataset.";
            if (Shard.Count == 1) File.WriteAllBytes(session.PathOf(RigPreviewPicture.FileName), RigPreviewPicture.Encode(FullPlan));
            if (Shard.Count > 1)
                ShardManifest.ForShard(Shard, CountsOf(FullPlan)).Write(session.WorkingFolder);
            session.Commit();
        }

        // A multi-view dynamic capture has count × steps views per split (TimePlanning.ViewCount).
        static ViewCounts CountsOf(CapturePlan plan) => new ViewCounts(
            TimePlanning.ViewCount(plan.Settings, plan.Time, DatasetSplit.Train), TimePlanning.ViewCount(plan.Settings, plan.Time, DatasetSplit.Val),
            TimePlanning.ViewCount(plan.Settings, plan.Time, DatasetSplit.Test));
    }
}
