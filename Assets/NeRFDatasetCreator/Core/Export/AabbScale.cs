using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// instant-ngp's <c>aabb_scale</c>. NGP maps a NeRF point x to x·scale + offset (defaults 0.33 and 0.5) and then
    /// trains inside the cube centred on 0.5 with side aabb_scale (testbed: aabb = [0.5, 0.5] inflated by
    /// 0.5·min(aabb_scale, 128)). The cube therefore covers |x| ≤ aabb_scale / (2·0.33) in output units, and the
    /// smallest power of two with 0.5·k ≥ 0.33·r covers a scene of radius r about the origin:
    /// k = 2^ceil(log2(0.66·r)), at least 1, at most 128. Radius 1.5 (nerf_synthetic's box) gives 1, as NGP's docs
    /// recommend for synthetic objects; the cameras may lie outside the cube.
    /// </summary>
    public static class AabbScale
    {
        public const double NgpScale = 0.33;
        public const int Max = 128;

        /// <summary>The aabb_scale for content within <paramref name="sceneRadius"/> output units of the origin.</summary>
        public static int ForRadius(double sceneRadius, ICollection<ValidationProblem> warnings = null)
        {
            if (double.IsNaN(sceneRadius) || double.IsInfinity(sceneRadius) || sceneRadius < 0)
                throw new InvalidParameterException(new[] { ValidationProblem.OutsideRange("sceneRadius", sceneRadius, 0, 1e9) });
            var needed = 2 * NgpScale * sceneRadius; // the cube's side in NGP units
            var k = 1;
            while (k < needed && k < Max) k *= 2;
            if (k < needed)
                warnings?.Add(new ValidationProblem("aabb_scale", ValidationProblem.Format(needed),
                    $"a scene of radius {ValidationProblem.Format(sceneRadius)} needs more than instant-ngp's largest aabb_scale {Max}; content beyond {ValidationProblem.Format(MaxRadius)} output units is cut off.",
                    "Normalise the scene (recentre and scale to the target)."));
            return k;
        }

        /// <summary>Radius (output units) covered by a given aabb_scale.</summary>
        public static double CoveredRadius(int aabbScale) => Math.Min(aabbScale, Max) / (2 * NgpScale);

        public static double MaxRadius => CoveredRadius(Max);
    }
}
