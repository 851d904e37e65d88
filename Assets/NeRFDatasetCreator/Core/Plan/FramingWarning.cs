using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A plan warning when a fixed distance leaves the target small in the frame (issue 33: the default distance 4 with
    /// a tiny target, and no word about it). The measure is <see cref="AutoDistanceRule"/>'s: the target's bounding
    /// sphere (radius b) at distance R subtends a half-angle asin(b/R), and it spans sin(asin(b/R)) / sin(θ/2) = b / (R·sin(θ/2))
    /// of the narrower image side, θ the narrower field of view — "auto" makes that 1/margin (83 % by default). Below
    /// <see cref="MinimumFill"/> most pixels are background and the target gets few rays or Gaussians: the warning
    /// states the fraction and suggests <c>"distance": "auto"</c>. Only for formations around a target of known size
    /// (the Unity side; the headless tool knows no bounds).
    /// </summary>
    public static class FramingWarning
    {
        /// <summary>The smallest share of the narrower image side the target's outline may span without a warning.</summary>
        public const double MinimumFill = 0.25;

        /// <summary>The share of the narrower image side the bounding sphere spans from <paramref name="distance"/>.</summary>
        public static double Fill(double boundingRadius, double distance, CameraIntrinsics intrinsics)
        {
            var narrowest = Math.Min(intrinsics.CameraAngleX, intrinsics.CameraAngleY);
            return boundingRadius / (distance * Math.Sin(narrowest / 2));
        }

        /// <summary>The warning, or null when the target fills enough, the distance is "auto", or the target's size is unknown.</summary>
        public static ValidationProblem For(DatasetSettings settings, PlanTarget target, double distance, CameraIntrinsics intrinsics)
        {
            if (settings.AutoDistance || !target.HasBounds || !(distance > target.BoundingRadius)) return null;
            if (!CameraSourcePlanning.AnyFormation(settings) || VolumePlanning.InsideOutWarning(settings) != null) return null;
            var fill = Fill(target.BoundingRadius, distance, intrinsics);
            if (fill >= MinimumFill) return null;
            var auto = AutoDistanceRule.Distance(target.BoundingRadius, settings.Camera.VerticalFovDegrees, settings.Width, settings.Height, settings.AutoDistanceMargin);
            return new ValidationProblem("distance", ValidationProblem.Format(distance),
                "leaves the target small: its bounding sphere (radius " + ValidationProblem.Format(Math.Round(target.BoundingRadius, 4)) + ") spans " + Percent(fill) +
                " of the image's narrower side (below " + Percent(MinimumFill) + "), so most pixels are background and the target gets few rays.",
                "Use \"distance\": \"auto\" (here " + ValidationProblem.Format(Math.Round(auto, 3)) + ", filling " + Percent(1 / settings.AutoDistanceMargin) + "), or a smaller distance.");
        }

        static string Percent(double fraction) => (fraction * 100).ToString("0.#", CultureInfo.InvariantCulture) + " %";
    }
}
