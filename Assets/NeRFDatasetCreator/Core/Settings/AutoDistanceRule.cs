using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The automatic camera distance: far enough that the target's bounding sphere (radius b about the target's
    /// centre) fits the narrower of the two fields of view θ with room to spare. A sphere at distance R subtends
    /// a half-angle asin(b/R); asking sin of that to be sin(θ/2)/margin gives R = margin·b / sin(θ/2). With the
    /// default margin 1.2 the sphere's outline fills about 83 % of the narrower image side at any FOV.
    /// </summary>
    public static class AutoDistanceRule
    {
        public const double DefaultMargin = 1.2;
        public const double MinMargin = 1;
        public const double MaxMargin = 10;

        public static double Distance(double boundingRadius, double verticalFovDegrees, int width, int height, double margin)
        {
            InvalidParameterException.ThrowIfAny(
                !(boundingRadius > 0) || double.IsInfinity(boundingRadius)
                    ? new ValidationProblem("boundingRadius", ValidationProblem.Format(boundingRadius), "must be a finite number above 0.",
                        "Give the target a renderer with non-empty bounds, or set a fixed distance.")
                    : null,
                ValidationProblem.OutsideRange("autoDistanceMargin", margin, MinMargin, MaxMargin));
            var intrinsics = CameraIntrinsics.FromVerticalFov(verticalFovDegrees, width, height);
            var narrowest = Math.Min(intrinsics.CameraAngleX, intrinsics.CameraAngleY);
            return margin * boundingRadius / Math.Sin(narrowest / 2);
        }
    }
}
