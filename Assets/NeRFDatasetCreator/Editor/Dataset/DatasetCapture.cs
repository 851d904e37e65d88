using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Settings and a target GameObject in, a dataset on disk out — the one path the window, batch mode and tests
    /// use. Main thread only. Everything decided here lives in Core (<see cref="DatasetRun"/>,
    /// <see cref="ViewPipeline"/>); this class only moves data between Unity objects and Core.
    /// </summary>
    public static class DatasetCapture
    {
        /// <summary>
        /// Centre and bounding-sphere radius (the sphere around the axis-aligned box) of the meshes the capture renders
        /// (<see cref="TargetMeshes"/>), in world space. Radius 0 at the target's position when it has none.
        /// </summary>
        public static PlanTarget MeasureTarget(GameObject target)
        {
            if (target == null) return PlanTarget.AtOrigin;
            var bounds = TargetMeshes.WorldBounds(target);
            if (!bounds.HasValue) return new PlanTarget(ToCore(target.transform.position), 0);
            return new PlanTarget(ToCore(bounds.Value.center), bounds.Value.extents.magnitude);
        }

        /// <summary>
        /// Checks the settings, the target and this editor, and plans the views. Never throws for user errors: read
        /// <see cref="PreparedCapture.Problems"/>. <paramref name="datasetFolder"/> overrides the settings' output
        /// folder and name (batch mode's -nerfOut).
        /// </summary>
        public static PreparedCapture Prepare(DatasetSettings settings, GameObject target, string projectRoot,
            ShardSpec shard = default, string datasetFolder = null)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            PrepareCalls++;
            IsPreparing = true;
            try
            {
                return PrepareNow(settings, target, projectRoot, shard, datasetFolder);
            }
            finally
            {
                IsPreparing = false;
            }
        }

        /// <summary>
        /// True while <see cref="Prepare"/> runs: its copies (time measurement, animated and Cinemachine cameras) may raise
        /// hierarchy and object-change events, which the window must not take for the user's edits (review S3-2).
        /// </summary>
        public static bool IsPreparing { get; private set; }

        /// <summary>How many times <see cref="Prepare"/> has run in this domain: the window's tests count its re-checks.</summary>
        public static int PrepareCalls { get; private set; }

        static PreparedCapture PrepareNow(DatasetSettings settings, GameObject target, string projectRoot, ShardSpec shard, string datasetFolder)
        {
            settings = settings.Clone();
            var given = settings.Clone();
            VolumeSource.ClearCache(); // the preview may read the obstacles from a cache; a capture reads the scene now
            var problems = new List<ValidationProblem>();
            var extraWarnings = new List<ValidationProblem>();
            var template = FindTemplateCamera(settings.Camera.CopyFromCamera, problems);
            if (template != null)
            {
                // The written intrinsics must be those of the camera that renders: a physical template's framing at
                // this W × H (gate fit), or a refusal when a pinhole cannot reproduce it.
                var framing = TemplateFraming.Problem(template, settings.Width, settings.Height, settings.Camera.CopyFromCamera);
                if (framing != null) problems.Add(framing);
                else if (settings.Width > 0 && settings.Height > 0)
                    settings.Camera.VerticalFovDegrees = TemplateFraming.VerticalFieldOfView(template, settings.Width, settings.Height);
                else settings.Camera.VerticalFovDegrees = template.fieldOfView;
                settings.Camera.NearClip = template.nearClipPlane;
                settings.Camera.FarClip = template.farClipPlane;
                CheckCullingMask(template, target, settings.Camera.CopyFromCamera, problems, extraWarnings);
            }
            // Scene and animated cameras are read from the scene first; then every source sets its split's count and, when
            // asked, the field of view (and an imported file's size) the camera renders with.
            SceneCameraSources.Resolve(settings);
            settings = CameraSourcePlanning.Resolved(settings, out _);
            var options = OptionsFor(settings, template);
            if (settings.Background != null && settings.Background.Sky)
            {
                options.Skybox = SkyboxOf(template);
                if (options.Skybox == null)
                    problems.Add(new ValidationProblem("background", "\"sky\"", "needs a skybox material, but " +
                        (template != null ? "the template camera has no Skybox component and " : "") + "the active scene has none.",
                        "Assign a Skybox Material in the Lighting window (Environment), or use \"transparent\" or a colour."));
            }
            try
            {
                CaptureSession.CheckTarget(target, options.Isolation);
            }
            catch (CaptureException e)
            {
                problems.Add(new ValidationProblem("target", target == null ? "none" : target.name, e.Message, ""));
            }
            try
            {
                CaptureEnvironment.ThrowIfCannotRender(options.EffectivePasses);
            }
            catch (CaptureException e)
            {
                problems.Add(new ValidationProblem("capture", CaptureEnvironment.RenderPipelineName, e.Message, ""));
            }
            // URP renderer features run in both colour renders (review S3-1): Full Screen Pass is refused, unknown ones warned.
            var features = UrpRendererFeatures.Read(out var rendererName);
            if (features != null)
                RendererFeatureCheck.Check(rendererName, features, settings.Background != null && settings.Background.Sky, problems, extraWarnings);
            var occlusion = UrpRendererFeatures.GpuOcclusionCullingWarning();
            if (occlusion != null) extraWarnings.Add(occlusion);

            var timeWarnings = new List<ValidationProblem>();
            var measured = TimeMeasurement.Measure(target, settings, MeasureTarget(target), timeWarnings);
            var run = DatasetRun.Prepare(settings, measured, projectRoot, shard, datasetFolder);
            problems.AddRange(run.Problems);
            if (run.IsValid && run.Plan.Time != null)
            {
                var clock = new ContentClock(run.Plan.Time.Sources, settings.Seed);
                var views = run.Plan.Views;
                options.BeforeView = (root, index) => clock.Show(root, views[index].Time.Value.Seconds);
                // Motion blur in a dynamic capture: the content moves over the shutter (ShutterMotion.SecondsAt).
                options.BeforeSubFrame = (root, sub, camera) =>
                {
                    if (sub.Seconds.HasValue) clock.Show(root, sub.Seconds.Value);
                };
            }
            if (run.IsValid)
            {
                // Issue 38: material passes and relighting renders, in Unity's terms (MaterialPassSelection, RelightingInUnity).
                options.MaterialPasses = MaterialPassSelection.Kinds(run.Plan.Settings.Materials);
                options.Relighting = RelightingInUnity.Resolve(run.Plan.Settings.Relighting, run.Plan.Normalisation);
            }
            if (run.IsValid && ShutterPlanning.IsOn(run.Plan.Settings))
            {
                var blur = run.Plan.Settings.MotionBlur;
                var blurredViews = run.Plan.Views;
                options.SubFramesOf = index => blurredViews[index].Motion == null ? null : SubFrameSchedule.For(blurredViews[index].Motion, blur.SubFrames);
                options.RollingShutterReadout = blur.Readout;
            }
            // The point cloud's meshes are read when a run starts (ReadSurface), not here: the window calls Prepare as
            // the user types, and copying a large model's arrays each time would make the editor stutter.
            var warnings = new List<ValidationProblem>(run.IsValid ? run.FullPlan.Warnings.Concat(timeWarnings) : Array.Empty<ValidationProblem>());
            warnings.AddRange(extraWarnings);
            return new PreparedCapture(run, target, options, problems, warnings) { Settings = given, ProjectRoot = projectRoot };
        }

        /// <summary>
        /// Captures and writes the whole dataset (or shard) before returning — after the preflight of a large capture
        /// (<see cref="PreflightCapture"/>) — and checks it (<see cref="PostCaptureCheck"/>: the result's
        /// <see cref="DatasetCaptureResult.Check"/>, <see cref="DatasetCheck.ReportFileName"/> in the dataset). Never throws
        /// for user or I/O errors.
        /// </summary>
        public static DatasetCaptureResult RunBlocking(PreparedCapture prepared, ICaptureProgress progress = null, string tool = "unity-editor")
        {
            if (!prepared.IsValid) return Refused(prepared.Problems);
            // A self-check still reading the last dataset counts as busy: a replace under the same name would swap the folder under it.
            if (ActiveCapture.IsRunning || PostCaptureCheck.IsRunning) return Busy();
            var preflight = PreflightCapture.Run(prepared);
            if (preflight != null) return preflight;
            var unreadable = ReadSurface(prepared) ?? CollectLabels(prepared);
            if (unreadable != null) return unreadable;
            DatasetWriteSession session;
            try
            {
                session = prepared.Run.Begin();
            }
            catch (Exception e) when (e is InvalidParameterException || e is IOException || e is UnauthorizedAccessException)
            {
                return Failed(prepared, null, e, 0);
            }
            LogEarlierRuns(session);
            try
            {
                HoldGeometrySteps(prepared);
                prepared.UnityFrame = UnityFrameCapture.Of(prepared.Target);
            }
            catch (Exception e)
            {
                return Failed(prepared, session, e, 0);
            }
            using (var consumer = Writers(prepared, session, out var pipeline))
            {
                DatasetCaptureResult result;
                try
                {
                    var summary = CaptureRunner.RunBlocking(prepared.Target, Poses(prepared), prepared.Options, consumer, progress);
                    result = Finish(prepared, session, pipeline, summary, tool);
                }
                catch (Exception e)
                {
                    return Failed(prepared, session, e, consumer.Written);
                }
                return result.Succeeded ? CheckBlocking(result) : result;
            }
        }

        /// <summary>
        /// The run's writer threads: each view's readback becomes Core raw frames (<see cref="DatasetViewWriter"/>) and goes
        /// through Core's <paramref name="pipeline"/> (the plan's lens, blur/sharp, the file writer, whose statistics
        /// <see cref="Finish"/> reads), one view per worker. Both run modes write through this one pipeline.
        /// </summary>
        static ParallelViewConsumer Writers(PreparedCapture prepared, DatasetWriteSession session, out ViewPipeline pipeline)
        {
            pipeline = new ViewPipeline(prepared.Run.Plan, session, UnityExr.Encode, prepared.Labels);
            // Views alive at once bounded by memory (a lens capture's are large): fewer readbacks, writers, queued views.
            var limit = CaptureMemory.Bound(prepared.Options, ParallelViewConsumer.DefaultWorkerCount);
            prepared.Options.ReadbacksInFlight = limit.Readbacks;
            return new ParallelViewConsumer(new DatasetViewWriter(prepared.Run.Plan.Views, pipeline), limit.Writers, limit.Queue);
        }

        /// <summary>The self-check of a finished dataset, blocking: a progress bar in the editor, log lines in batch mode.</summary>
        static DatasetCaptureResult CheckBlocking(DatasetCaptureResult result)
        {
            var lastLog = DateTime.UtcNow;
            var drawn = false;
            var report = PostCaptureCheck.RunBlocking(result.DatasetFolder, (done, total) =>
            {
                if (Application.isBatchMode)
                {
                    if ((DateTime.UtcNow - lastLog).TotalSeconds < 2) return;
                    lastLog = DateTime.UtcNow;
                    Debug.Log(string.Format(CultureInfo.InvariantCulture, "NeRF Dataset Creator: checking the dataset: step {0} of {1}", done, total));
                    return;
                }
                drawn = true;
                UnityEditor.EditorUtility.DisplayProgressBar("NeRF Dataset Creator: checking the dataset", done + " of " + total, total > 0 ? (float)done / total : 0);
            });
            if (drawn) UnityEditor.EditorUtility.ClearProgressBar();
            return result.WithCheck(report);
        }

        /// <summary>
        /// Starts the capture on editor updates (the editor stays usable; progress and Cancel in Background Tasks).
        /// A large capture's preflight (<see cref="PreflightCapture"/>, a few seconds) runs first, blocking. After a
        /// successful capture the dataset is checked off the main thread (<see cref="PostCaptureCheck"/>), and
        /// <paramref name="done"/> gets the result once the check is in.
        /// <paramref name="done"/> runs on the main thread with the result, which is also logged to the Console (the
        /// run may outlive the window that started it, and Play mode, a script reload or quitting end it from inside
        /// that editor event: the log then says why and where the partial files are). Returns the session (its
        /// Cancel() stops the run), or null when the capture could not start — <paramref name="done"/> has then
        /// already been called. <paramref name="captured"/>, when given, gets the capture's result as soon as the dataset is
        /// in place, before the self-check starts: the window stores it there (in <c>SessionState</c>, which outlives a
        /// domain reload), so a check ended by Play mode or a reload (<see cref="BackgroundJob"/>) never loses the fact
        /// that the capture itself succeeded (review R4-9).
        /// </summary>
        public static CaptureSession StartInBackground(PreparedCapture prepared, Action<DatasetCaptureResult> done, string tool = "unity-editor",
            Action<DatasetCaptureResult> captured = null)
        {
            var refused = !prepared.IsValid ? Refused(prepared.Problems) : ActiveCapture.IsRunning || PostCaptureCheck.IsRunning ? Busy() : PreflightCapture.Run(prepared) ?? ReadSurface(prepared) ?? CollectLabels(prepared);
            if (refused != null)
            {
                Log(refused);
                done?.Invoke(refused);
                return null;
            }
            DatasetWriteSession session = null;
            ParallelViewConsumer consumer = null;
            try
            {
                session = prepared.Run.Begin();
                LogEarlierRuns(session);
                HoldGeometrySteps(prepared);
                prepared.UnityFrame = UnityFrameCapture.Of(prepared.Target);
                consumer = Writers(prepared, session, out var pipeline);
                var written = consumer;
                return CaptureRunner.RunInBackground(prepared.Target, Poses(prepared), prepared.Options, consumer, (summary, error) =>
                {
                    var result = error == null
                        ? Finish(prepared, session, pipeline, summary, tool)
                        : Failed(prepared, session, error, written.Written);
                    written.Dispose();
                    Log(result);
                    if (!result.Succeeded)
                    {
                        done?.Invoke(result);
                        return;
                    }
                    captured?.Invoke(result);
                    // The self-check runs off the main thread; done gets the result once it is in.
                    PostCaptureCheck.StartInBackground(result.DatasetFolder, report =>
                    {
                        var checkedResult = result.WithCheck(report);
                        LogCheck(checkedResult);
                        done?.Invoke(checkedResult);
                    });
                });
            }
            catch (Exception e)
            {
                var written = consumer?.Written ?? 0;
                consumer?.Dispose();
                var result = Failed(prepared, session, e, written);
                Log(result);
                done?.Invoke(result);
                return null;
            }
        }

        /// <summary>The self-check's summary in the Console: information when it passed, an error when it found problems.</summary>
        public static void LogCheck(DatasetCaptureResult result)
        {
            if (result.Check == null) return;
            var text = "NeRF Dataset Creator: " + PostCaptureCheck.Summary(result.Check);
            if (result.CheckFailed) Debug.LogError(text);
            else Debug.Log(text);
        }

        /// <summary>A result in the Console: information, a warning after a cancel or interruption, else an error.</summary>
        public static void Log(DatasetCaptureResult result)
        {
            if (result.Succeeded && !result.CheckFailed) Debug.Log(result.Message);
            else if (result.Cancelled) Debug.LogWarning(result.Message);
            else Debug.LogError(result.Message);
        }

        static DatasetCaptureResult Finish(PreparedCapture prepared, DatasetWriteSession session, ViewPipeline pipeline,
            CaptureSummary summary, string tool)
        {
            var files = pipeline.Files;
            var provenance = new Provenance(DateTime.UtcNow, Application.unityVersion, tool);
            // unity_frame (issue 34): the target as it was when the run started, read before any view posed the scene.
            provenance.UnityFrame = prepared.UnityFrame ?? UnityFrameCapture.Of(prepared.Target);
            provenance.Statistics["views"] = summary.Views;
            provenance.Statistics["seconds"] = summary.Seconds;
            provenance.Statistics["viewsPerSecond"] = summary.ViewsPerSecond;
            provenance.Statistics["clampedDepthPixels"] = files.ClampedDepthPixels;
            files.Matting.WriteStatistics(provenance.Statistics);
            summary.Matting = files.Matting.Total;
            // Issue 38: which shaders the material passes read, for dataset_config.json's materials record and the Console.
            provenance.Materials = summary.Materials?.ToFacts();
            if (summary.Materials?.Warning() is string unreadMaterials) Debug.LogWarning("NeRF Dataset Creator: " + unreadMaterials);
            IReadOnlyList<CloudPoint> cloud = null;
            try
            {
                if (prepared.Surface != null && prepared.Run.WritesPointCloud)
                {
                    cloud = TargetPointCloud.Sample(prepared.Run.Plan, prepared.Surface);
                    provenance.Statistics["points3d"] = cloud.Count;
                }
                // The geometry pack is the target's surface, so an environment capture's whole scene is left out of it.
                var steps = prepared.GeometrySteps;
                if (steps != null)
                {
                    // "geometryPack": "everyStep": the copy made when the run started, posed at each step in turn here on the
                    // main thread; Core packs and writes each step on a worker, one step in flight (review R4-6).
                    var progress = new GeometryPackProgress();
                    try
                    {
                        prepared.Run.Finish(session, provenance, cloud, prepared.Surface, prepared.Labels, steps.At, progress.Report);
                    }
                    finally
                    {
                        progress.Close();
                    }
                    foreach (var warning in steps.Warnings.GroupBy(w => w.ToString()).Select(g => g.First())) Debug.LogWarning("NeRF Dataset Creator: " + warning);
                }
                else prepared.Run.Finish(session, provenance, cloud, WritesGeometryPack(prepared) ? prepared.Surface : null, prepared.Labels);
            }
            catch (Exception e)
            {
                return Failed(prepared, session, e, summary.Views);
            }
            finally
            {
                ReleaseGeometrySteps(prepared);
            }
            var message = string.Format(CultureInfo.InvariantCulture,
                "NeRF Dataset Creator: wrote {0} views to {1} in {2:0.0} s ({3:0.00} views/s).",
                summary.Views, session.FinalFolder, summary.Seconds, summary.ViewsPerSecond);
            if (files.WriteSeconds > 0)
                message += string.Format(CultureInfo.InvariantCulture,
                    " Writer threads were busy {0:0.0} s ({1:0.0} ms per view), {2:0} % of it in PNG encoding.",
                    files.WriteSeconds, 1000 * files.WriteSeconds / Math.Max(1, files.ViewsWritten), 100 * files.PngEncodeSeconds / files.WriteSeconds);
            if (cloud != null && cloud.Count > 0)
            {
                var region = TargetPointCloud.Region(prepared.Run.Plan);
                message += string.Format(CultureInfo.InvariantCulture, " points3d.ply holds {0} surface points", cloud.Count) +
                           (region == null ? "." : string.Format(CultureInfo.InvariantCulture, " within {0:0.##} units of the capture volumes' centre {1}{2}.",
                               region.Radius, region.Centre, region.Automatic ? " (pointCloudRadius 0: " + TargetPointCloud.DefaultRadiusFactor.ToString(CultureInfo.InvariantCulture) + " × the boxes' half-diagonal)" : ""));
                if (cloud.Count < prepared.Run.Plan.Settings.PointCloudPoints)
                    Debug.LogWarning(string.Format(CultureInfo.InvariantCulture,
                        "NeRF Dataset Creator: points3d.ply holds {0} of the {1} points asked for: almost none of the surface near the sphere lies inside it. Raise pointCloudRadius for more.",
                        cloud.Count, prepared.Run.Plan.Settings.PointCloudPoints));
            }
            if (files.ClampedDepthPixels > 0)
                message += string.Format(CultureInfo.InvariantCulture,
                    " {0} depth pixels lay beyond 65.535 output units and were clamped in the 16-bit depth PNGs (the EXR files keep them).",
                    files.ClampedDepthPixels);
            if (files.Matting.ViewsCounted > 0) message += " Matting: " + files.Matting.Total + ".";
            if (prepared.Run.FlowSummary != null) message += " " + prepared.Run.FlowSummary;
            var mattingWarning = files.Matting.Warning();
            if (mattingWarning != null) Debug.LogWarning(mattingWarning);
            return new DatasetCaptureResult(true, false, session.FinalFolder, null, message, summary.Views, summary.ViewsPerSecond);
        }

        static DatasetCaptureResult Failed(PreparedCapture prepared, DatasetWriteSession session, Exception error, int written)
        {
            ReleaseGeometrySteps(prepared);
            var cancelled = error is OperationCanceledException;
            var interruption = (error as CaptureCancelledException)?.Interruption;
            var what = interruption != null ? "The capture was stopped after " + written + " written views because " + interruption + "."
                : cancelled ? "The capture was cancelled after " + written + " written views."
                : "The capture failed: " + Describe(error);
            // The run is over: its partial folder is now a leftover that clean may remove, no longer a capture in progress.
            session?.End();
            var where = session == null ? "" : " " + session.DescribeAbandoned();
            return new DatasetCaptureResult(false, cancelled, null, session?.PartialFolder, "NeRF Dataset Creator: " + what + where, written, 0);
        }

        /// <summary>A second capture while one (or its self-check) runs: refused before anything (a working folder) is created.</summary>
        static DatasetCaptureResult Busy() => new DatasetCaptureResult(false, false, null, null,
            "NeRF Dataset Creator: nothing was captured — " + (ActiveCapture.IsRunning ? ActiveCapture.BusyMessage
                : "the self-check of the last capture is still running; wait for it or cancel it in Window ▸ General ▸ Background Tasks."), 0, 0);

        /// <summary>What Begin found of earlier runs on this output (Core's Recovery): interrupted ones it finished or rolled back, leftovers.</summary>
        static void LogEarlierRuns(DatasetWriteSession session)
        {
            // A refused journal (a path outside what its operation owns) changed nothing and needs the user's eye.
            foreach (var note in session.Recovered)
                if (note.Refused) Debug.LogWarning("NeRF Dataset Creator: " + note);
                else Debug.Log("NeRF Dataset Creator: " + note);
            foreach (var leftover in session.Leftovers)
                Debug.LogWarning("NeRF Dataset Creator: left over: " + leftover + " Delete it, or run `nerf-dataset clean " + Path.GetDirectoryName(session.FinalFolder) + "`.");
        }

        static DatasetCaptureResult Refused(IEnumerable<ValidationProblem> problems) => new DatasetCaptureResult(false, false, null, null,
            "NeRF Dataset Creator: nothing was captured —\n" + string.Join("\n", problems.Select(p => "  " + p)), 0, 0);

        /// <summary>
        /// Reads the target's meshes for points3d.ply at the start of a run, with the scene as it is captured; a result
        /// that refuses the run when they give nothing to sample, null when all is well (or no cloud is asked for).
        /// </summary>
        static DatasetCaptureResult ReadSurface(PreparedCapture prepared)
        {
            if (!prepared.Run.WritesPointCloud && !WritesGeometryPack(prepared)) return null;
            var warnings = new List<ValidationProblem>();
            // A dynamic capture's cloud is the surface at its first time step (the user's target is only read); a
            // whole-scene capture (an inside-out volume) samples every mesh it renders, not only the target's.
            var plan = prepared.Run.Plan;
            prepared.Surface = prepared.Options.Isolation == CaptureIsolation.WholeScene
                ? TargetSurface.CollectScene(warnings)
                : TimeMeasurement.SurfaceAtStart(prepared.Target, plan.Time, plan.Settings.Seed, warnings) ?? TargetSurface.Collect(prepared.Target, warnings);
            foreach (var warning in warnings) Debug.LogWarning("NeRF Dataset Creator: " + warning);
            if (!prepared.Run.WritesPointCloud) return null; // a target without meshes simply has no geometry pack
            var problems = TargetPointCloud.Check(prepared.Run.Plan, prepared.Surface);
            return problems.Count == 0 ? null : Refused(problems);
        }

        /// <summary>
        /// The label table and each renderer's ids (<see cref="SceneLabels"/>), read when the run starts with the scene as it
        /// is captured, when the settings write id maps; a result that refuses the run when the rules give too many ids,
        /// null when all is well. Without labels the capture has no labels pass.
        /// </summary>
        static DatasetCaptureResult CollectLabels(PreparedCapture prepared)
        {
            var settings = prepared.Run.Plan.Settings.Labels;
            prepared.Labels = null;
            prepared.Options.Labels = null;
            if (settings == null || !settings.Enabled) return null;
            try
            {
                var template = prepared.Options.TemplateCamera;
                var labels = SceneLabels.Collect(settings, prepared.Target, prepared.Options.Isolation, template != null ? template.cullingMask : ~0,
                    prepared.Run.Plan.Time != null);
                prepared.Labels = labels.Table;
                prepared.Options.Labels = labels.Ids;
                return null;
            }
            catch (InvalidParameterException e)
            {
                return Refused(e.Problems);
            }
        }

        /// <summary>
        /// <c>"geometryPack": "everyStep"</c>: copies the target when the run starts, with the scene as it is captured (the
        /// capture's own copy is made from the same state), so that an edit during a background run never reaches the pack;
        /// posed at each step when the dataset is finished (review R4-6). Nothing for other captures.
        /// </summary>
        static void HoldGeometrySteps(PreparedCapture prepared)
        {
            ReleaseGeometrySteps(prepared);
            if (!WritesGeometryPack(prepared) || !GeometryPackWriter.WritesEveryStep(prepared.Run.Plan)) return;
            var plan = prepared.Run.Plan;
            prepared.GeometrySteps = new TargetSurfaceOverTime(prepared.Target, plan.Time, plan.Settings.Seed, new List<ValidationProblem>());
        }

        static void ReleaseGeometrySteps(PreparedCapture prepared)
        {
            prepared.GeometrySteps?.Dispose();
            prepared.GeometrySteps = null;
        }

        /// <summary>
        /// Whether the capture writes <c>geometry/target_mesh.ply</c>: a whole dataset (Core's
        /// <see cref="DatasetRun.WritesGeometryPack"/>, false with <c>"geometryPack": false</c>) of a target, not an
        /// environment's whole scene. The meshes are the ones ReadSurface collects for points3d.ply — the same renderers,
        /// LOD, skinning pose and (dynamic) start time; with the pack off and no points3d.ply, none are collected.
        /// </summary>
        internal static bool WritesGeometryPack(PreparedCapture prepared) =>
            prepared.Run.WritesGeometryPack && prepared.Options.Isolation != CaptureIsolation.WholeScene;

        static string Describe(Exception e)
        {
            var capture = e as CaptureException ?? ParallelViewConsumer.Explain(e);
            return capture?.Message ?? e.Message;
        }

        static IReadOnlyList<UnityPose> Poses(PreparedCapture prepared) => prepared.Run.Plan.Views.Select(v => v.Pose).ToList();

        /// <summary>
        /// The sky an environment capture draws: the template camera's own enabled Skybox component, which is what that
        /// camera draws (Manual: class-Skybox), else the active scene's <c>RenderSettings.skybox</c> (read here, outside
        /// any lighting override, so it is the user's scene's).
        /// </summary>
        static Material SkyboxOf(Camera template)
        {
            if (template != null && template.TryGetComponent<Skybox>(out var own) && own.enabled && own.material != null) return own.material;
            return RenderSettings.skybox;
        }

        static CaptureOptions OptionsFor(DatasetSettings settings, Camera template)
        {
            var splits = DatasetSplits.All.Select(settings.Split).ToList();
            // Alpha comes from the colour pair. The mask pass runs for the mask images and, over a clear background, for
            // the matting diagnostics: a sample outside the geometry must show the clear colours (MattingDiagnostics).
            // A sky fills both halves, so there it runs only for the mask images.
            var passes = CapturePasses.Color;
            var sky = settings.Background != null && settings.Background.Sky;
            if (splits.Any(s => s.Count > 0 && s.Mask) || !sky) passes |= CapturePasses.Mask;
            if (splits.Any(s => s.Count > 0 && s.Depth != ExtraOutput.None)) passes |= CapturePasses.Depth;
            if (splits.Any(s => s.Count > 0 && s.Normal != ExtraOutput.None)) passes |= CapturePasses.Normal;
            var options = new CaptureOptions
            {
                Width = settings.Width,
                Height = settings.Height,
                Supersampling = settings.Supersampling,
                Passes = passes,
                VerticalFieldOfViewDegrees = settings.Camera.VerticalFovDegrees,
                NearClip = settings.Camera.NearClip,
                FarClip = settings.Camera.FarClip,
                TemplateCamera = template,
                // Inside-out views need the surroundings: a dataset with a volume split copies every root object of the
                // loaded scenes (the mask then covers all geometry), not just the target.
                Isolation = splits.Any(s => s.Count > 0 && s.Source != null && s.Source.IsVolume) ? CaptureIsolation.WholeScene : CaptureIsolation.TargetOnly,
            };
            LensOptions.Apply(settings, options);
            return options;
        }

        /// <summary>
        /// A template camera whose culling mask leaves out layers of the target's renderers: a warning when some would
        /// be missing from every image, an error when all would (Core's <see cref="CullingMaskCheck"/>).
        /// </summary>
        static void CheckCullingMask(Camera template, GameObject target, string cameraName, List<ValidationProblem> errors, List<ValidationProblem> warnings)
        {
            if (target == null) return;
            var layers = TargetMeshes.Of(target).Select(pair => pair.Key.gameObject.layer).ToList();
            if (layers.Count == 0) return;
            var problem = CullingMaskCheck.Check(template.cullingMask, layers, LayerMask.LayerToName, cameraName, out var isError);
            if (problem != null) (isError ? errors : warnings).Add(problem);
        }

        /// <summary>The scene camera named by the settings (hierarchy path or name), or null for the built-in defaults.</summary>
        static Camera FindTemplateCamera(string pathOrName, List<ValidationProblem> problems)
        {
            if (string.IsNullOrWhiteSpace(pathOrName)) return null;
            var found = SceneObjects.Find(pathOrName);
            var camera = found == null ? null : found.GetComponent<Camera>();
            if (camera == null)
                problems.Add(new ValidationProblem("camera.copyFromCamera", pathOrName,
                    found == null ? "names no object in the open scenes." : "names an object without a Camera.",
                    "Give the hierarchy path or name of a scene camera, or leave it empty for the built-in camera."));
            return camera;
        }

        static Vector3d ToCore(Vector3 v) => new Vector3d(v.x, v.y, v.z);
    }
}
