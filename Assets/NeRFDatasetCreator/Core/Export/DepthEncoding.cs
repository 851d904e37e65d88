using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The depth rule shared by every export. A depth value is a z-depth (distance along the camera's viewing axis,
    /// not along the ray) in OUTPUT units: metric z (Unity units) × the normalisation scale s, so that depth and
    /// poses describe the same world. The 16-bit PNG stores round(z_out / step) with step = 0.001 output units
    /// (nerfstudio's default depth_unit_scale_factor, instant-ngp's integer_depth_scale); 0 means no hit.
    /// </summary>
    public static class DepthEncoding
    {
        /// <summary>Largest representable output depth with the default step: 65.535 output units.</summary>
        public static double MaxEncodable(double step = ExportScene.DefaultDepthUnitScale) => ushort.MaxValue * step;

        /// <summary>z in output units from metric z and the applied scale.</summary>
        public static double ToOutputUnits(double metricDepth, double normalisationScale) => metricDepth * normalisationScale;

        /// <summary>
        /// The 16-bit PNG value of an output depth. No hit, non-finite and out-of-range depths become 0 ("unknown"
        /// for both nerfstudio and instant-ngp) rather than a clamped, wrong distance.
        /// </summary>
        public static ushort ToPngValue(double outputDepth, double step = ExportScene.DefaultDepthUnitScale)
        {
            if (double.IsNaN(outputDepth) || double.IsInfinity(outputDepth) || outputDepth <= 0) return 0;
            var steps = Math.Round(outputDepth / step, MidpointRounding.AwayFromZero);
            return steps >= 1 && steps <= ushort.MaxValue ? (ushort)steps : (ushort)0;
        }
    }
}
