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
        public static IEnumerable<ValidationProblem> For(DatasetSettings settings, PlanTarget target, CameraIntrinsics intrinsics, IEnumerable<PlannedView> views)
        {
            if (!ShutterPlanning.IsOn(settings)) yield break;
            var n = settings.MotionBlur.SubFrames;
            double longest = 0;
            var count = 0;
            PlannedView worst = null;
            foreach (var view in views)
            {
                if (view.Motion == null) continue;
                var length = Length(view, target, intrinsics);
                if (length > n) count++;
                if (length > longest)
                {
                    longest = length;
                    worst = view;
                }
            }
            if (count == 0) yield break;
            yield return new ValidationProblem("motionBlur.subFrames", n.ToString(CultureInfo.InvariantCulture),
                "is fewer than the blur's length in pixels in " + count.ToString(CultureInfo.InvariantCulture) + " view(s) (longest " +
                ValidationProblem.Format(Math.Round(longest, 1)) + " px, " + worst.FramePath + "): the sub-frames are more than a pixel apart there, so the blur shows " +
                n + " separate copies (error up to " + ValidationProblem.Format(Math.Round(0.5 / n, 4)) + " of the contrast).",
                "Raise motionBlur.subFrames to " + ((int)Math.Ceiling(longest)).ToString(CultureInfo.InvariantCulture) + " or more, or shorten motionBlur.shutter or the shake.");
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
