using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A plan warning when the camera's motion blurs the target further than the sub-frames cover smoothly: the image of
    /// the target's centre and of four points on its bounding sphere (across and up from the view) moves L pixels between
    /// the start and end pose; with L &gt; <c>subFrames</c> the sub-frames are more than a pixel apart and the average
    /// ghosts (error up to 1/(2N) of the contrast instead of L/(8N²); <see cref="SubFrameSchedule.ErrorBound"/>). Content
    /// motion in a dynamic capture is not measured here (it needs the scene).
    /// </summary>
    public static class BlurLengthWarning
    {
        /// <summary>One warning per split with views whose blur is longer than <c>subFrames</c> pixels, with advice that can be followed.</summary>
        public static IEnumerable<ValidationProblem> For(DatasetSettings settings, PlanTarget target, CameraIntrinsics intrinsics, IEnumerable<PlannedView> views)
        {
            if (!ShutterPlanning.IsOn(settings)) yield break;
            var n = settings.MotionBlur.SubFrames;
            var count = new int[DatasetSplits.All.Count];
            var total = new int[DatasetSplits.All.Count];
            var longest = new double[DatasetSplits.All.Count];
            var worst = new PlannedView[DatasetSplits.All.Count];
            foreach (var view in views)
            {
                if (view.Motion == null) continue;
                var s = (int)view.Split;
                total[s]++;
                var length = Length(view, target, intrinsics);
                if (length > n) count[s]++;
                if (length > longest[s])
                {
                    longest[s] = length;
                    worst[s] = view;
                }
            }
            foreach (var split in DatasetSplits.All)
            {
                var s = (int)split;
                if (count[s] == 0) continue;
                yield return new ValidationProblem("motionBlur.subFrames", n.ToString(CultureInfo.InvariantCulture),
                    "is fewer than the blur's length in pixels in " + count[s].ToString(CultureInfo.InvariantCulture) + " of " + total[s].ToString(CultureInfo.InvariantCulture) + " " +
                    DatasetSplits.Name(split) + " views (longest " + ValidationProblem.Format(Math.Round(longest[s], 1)) + " px, " + worst[s].FramePath +
                    "): the sub-frames are more than a pixel apart there, so the blur shows " + n + " separate copies (error up to " +
                    ValidationProblem.Format(Math.Round(0.5 / n, 4)) + " of the contrast).",
                    Fix(settings, split, longest[s]));
            }
        }

        /// <summary>
        /// Advice that can be followed: more sub-frames while that is within <see cref="MotionBlurSettings.MaxSubFrames"/>;
        /// beyond it a shorter shutter (the path blur is proportional to it) or shake, and for a split whose formation
        /// is random, a formation whose consecutive views are neighbours (a random formation's are far apart, so its
        /// path — the central difference of its neighbours — is long; issue 33: "Raise subFrames to 722").
        /// </summary>
        static string Fix(DatasetSettings settings, DatasetSplit split, double longest)
        {
            var needed = (int)Math.Ceiling(longest);
            if (needed <= MotionBlurSettings.MaxSubFrames)
                return "Raise motionBlur.subFrames to " + needed.ToString(CultureInfo.InvariantCulture) + " or more, or shorten motionBlur.shutter or the shake.";
            var max = MotionBlurSettings.MaxSubFrames;
            var scale = max / longest;
            var blur = settings.MotionBlur;
            var name = DatasetSplits.Name(split);
            if (blur.Camera == ShutterCameraMotion.Shake)
                return "No sub-frame count covers it (at most " + max + "): with motionBlur.subFrames " + max + ", shorten the shake to " +
                       ValidationProblem.Format(Math.Floor(scale * 1000) / 1000) + " × its length (motionBlur.shakeDistance " +
                       ValidationProblem.Format(Math.Floor(blur.ShakeDistance * scale * 1000) / 1000) + ", shakeDegrees " +
                       ValidationProblem.Format(Math.Floor(blur.ShakeDegrees * scale * 1000) / 1000) + " or less).";
            var shutter = ValidationProblem.Format(Math.Floor(blur.Shutter * scale * 1000) / 1000);
            var splitSettings = settings.Split(split);
            var random = (splitSettings.Source == null || splitSettings.Source.IsFormation) && splitSettings.Formation.Kind == FormationKind.Random;
            return random
                ? "No sub-frame count covers it (at most " + max + "): the " + name + " split's random formation puts consecutive views far apart, so the camera's path between them is long. " +
                  "Give splits." + name + " a formation whose views are neighbours (orbit, halo, semisphere or sphere), or set motionBlur.shutter to " + shutter + " or less with subFrames " + max + "."
                : "No sub-frame count covers it (at most " + max + "): set motionBlur.shutter to " + shutter + " or less with subFrames " + max + ", or use more views in splits." + name + " (closer neighbours).";
        }

        /// <summary>The largest image motion, in output pixels, of the target's centre and four points on its bounding sphere.</summary>
        public static double Length(PlannedView view, PlanTarget target, CameraIntrinsics intrinsics)
        {
            var mid = view.Pose;
            var radius = target.HasBounds ? target.BoundingRadius : 0;
            var probes = new[]
            {
                target.Centre,
                target.Centre + mid.Rotation.Right * radius, target.Centre - mid.Rotation.Right * radius,
                target.Centre + mid.Rotation.Up * radius, target.Centre - mid.Rotation.Up * radius,
            };
            double longest = 0;
            foreach (var p in probes)
            {
                if (!Project(view.Motion.Start, p, intrinsics, out var x0, out var y0) || !Project(view.Motion.End, p, intrinsics, out var x1, out var y1)) continue;
                longest = Math.Max(longest, Math.Sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0)));
            }
            return longest;
        }

        static bool Project(UnityPose pose, Vector3d point, CameraIntrinsics k, out double x, out double y)
        {
            var inverse = PoseInterpolation.Inverse(pose.Rotation);
            var c = inverse.Rotate(point - pose.Position); // Unity camera space: +Z forward, +Y up
            x = y = 0;
            if (!(c.Z > 1e-9)) return false;
            x = k.FlX * c.X / c.Z;
            y = k.FlY * c.Y / c.Z;
            return true;
        }
    }
}
