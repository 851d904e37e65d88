using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using UnityEditor;
using UnityEngine;
using Debug = UnityEngine.Debug;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The preflight of a large capture (issue 21): Core's <see cref="PreflightCheck"/> picks a handful of the plan's own
    /// views at low resolution; they are captured with the real target and settings into a fresh folder under the
    /// system's temporary folder, checked by <see cref="PostCaptureCheck"/>, and that folder is deleted again. A broken
    /// pipeline (a renderer feature, a pass flipped, a shader the data passes cannot follow) then stops the capture in
    /// seconds, in the check's words. <c>"preflight": false</c> turns it off.
    /// </summary>
    static class PreflightCapture
    {
        const string Prefix = "NeRF Dataset Creator: ";

        /// <summary>Null when no preflight is needed or it passed; otherwise the refusal to return instead of capturing.</summary>
        public static DatasetCaptureResult Run(PreparedCapture prepared)
        {
            var settings = prepared.Settings;
            var views = prepared.Run.FullPlan.Views.Count;
            if (!PreflightCheck.Needed(settings, views)) return null;

            // A new folder under a random name: everything in it is written by this call, so this call may delete it.
            var temp = Path.Combine(Path.GetTempPath(), PreflightCheck.FolderPrefix + Guid.NewGuid().ToString("N"));
            if (Directory.Exists(temp) || File.Exists(temp)) return null; // cannot happen with a fresh GUID; never touch it
            Directory.CreateDirectory(temp);
            try
            {
                var calibration = PreflightCheck.CalibrationSettings(settings, temp, "calibration");
                var plan = prepared.Run.FullPlan;
                var shard = PreflightCheck.Shard(plan.ViewsOf(DatasetSplit.Train).Count(), plan.ViewsOf(DatasetSplit.Val).Count(), plan.ViewsOf(DatasetSplit.Test).Count());
                var prepare = DatasetCapture.Prepare(calibration, prepared.Target, prepared.ProjectRoot, shard, Path.Combine(temp, "calibration"));
                if (!prepare.IsValid)
                    return Stop("its calibration capture could not be prepared:\n  " + string.Join("\n  ", prepare.Problems));
                Debug.Log(string.Format(CultureInfo.InvariantCulture,
                    Prefix + "preflight: capturing {0} of the {1} views at {2}×{3} into {4} and checking them before the full capture " +
                    "(\"preflight\": false turns this off).", prepare.ViewCount, views, calibration.Width, calibration.Height, temp));
                var result = DatasetCapture.RunBlocking(prepare, Application.isBatchMode ? new QuietProgress() : (ICaptureProgress)new ProgressBarReporter("NeRF Dataset Creator: preflight"), "unity-preflight");
                if (result.Cancelled) return Stop("the preflight was cancelled.", cancelled: true);
                if (!result.Succeeded) return Stop("its calibration capture failed: " + result.Message);
                if (result.Check == null || result.CheckFailed)
                    return Stop("the check of its calibration capture (" + prepare.ViewCount.ToString(CultureInfo.InvariantCulture) +
                                " of the plan's views, same target and settings, at low resolution) found problems, so the full capture would have them too.\n" +
                                (result.Check == null ? "" : PostCaptureCheck.Summary(result.Check)) +
                                "\nSee Documentation~/check.md for what each check means. Set \"preflight\": false to capture anyway.");
                Debug.Log(Prefix + "preflight passed: " + prepare.ViewCount.ToString(CultureInfo.InvariantCulture) + " calibration views checked.");
                EstimateGeometryPack(prepared);
                return null;
            }
            finally
            {
                try
                {
                    Directory.Delete(temp, true);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    Debug.LogWarning(Prefix + "the preflight's temporary folder " + temp + " could not be deleted (" + e.Message + "); delete it by hand.");
                }
            }
        }

        /// <summary>
        /// <c>"geometryPack": "everyStep"</c>: the calibration wrote the start mesh only (Core's
        /// <see cref="PreflightCheck.CalibrationSettings"/>), so the per-step pack is estimated instead of computed (review
        /// R4-6): one copy posed at the last step — the costliest, Animators step from 0 — times the number of steps, logged.
        /// </summary>
        static void EstimateGeometryPack(PreparedCapture prepared)
        {
            var plan = prepared.Run.Plan;
            if (!DatasetCapture.WritesGeometryPack(prepared) || !GeometryPackWriter.WritesEveryStep(plan)) return;
            var watch = Stopwatch.StartNew();
            using (var steps = new TargetSurfaceOverTime(prepared.Target, plan.Time, plan.Settings.Seed, new List<ValidationProblem>()))
            {
                watch.Restart();
                steps.At(plan.Time.Steps - 1);
            }
            var one = watch.Elapsed.TotalSeconds;
            Debug.Log(string.Format(CultureInfo.InvariantCulture,
                Prefix + "preflight: the geometry of every time step ({0} steps, \"geometryPack\": \"everyStep\") will take up to about {1:0.#} s " +
                "after the views ({2:0.###} s for the last step); the preflight did not compute it.", plan.Time.Steps, one * plan.Time.Steps, one));
        }

        static DatasetCaptureResult Stop(string why, bool cancelled = false) =>
            new DatasetCaptureResult(false, cancelled, null, null, Prefix + "nothing was captured — the preflight stopped the capture: " + why, 0, 0);

        /// <summary>No progress bar in batch mode (the calibration takes seconds) and never a cancel.</summary>
        sealed class QuietProgress : ICaptureProgress
        {
            public bool CancelRequested => false;

            public void Report(ThroughputMeter meter)
            {
            }

            public void Close()
            {
            }
        }
    }
}
