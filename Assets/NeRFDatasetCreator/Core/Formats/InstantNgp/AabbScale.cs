using System;
using System.Collections.Generic;
using System.Globalization;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// instant-ngp's <c>aabb_scale</c>. NGP maps a NeRF point x to x·scale + offset (defaults 0.33 and 0.5:
    /// NVlabs/instant-ngp <c>src/nerf_loader.cu</c> lines 403–404, <c>NERF_SCALE</c> in
    /// <c>include/neural-graphics-primitives/nerf_loader.h</c> line 29) and then trains inside the cube centred on 0.5
    /// with side aabb_scale (<c>src/testbed_nerf.cu</c> lines 2424–2425: <c>m_aabb = BoundingBox{vec3(0.5f), vec3(0.5f)};
    /// m_aabb.inflate(0.5f * std::min(1 &lt;&lt; (NERF_CASCADES() - 1), aabb_scale))</c>, NERF_CASCADES() = 8). The cube
    /// therefore covers |x| ≤ aabb_scale / (2·0.33) in output units on every axis, and the smallest power of two with
    /// 0.5·k ≥ 0.33·r covers a scene of radius r about the origin: k = 2^ceil(log2(0.66·r)), at least 1, at most 128
    /// (NGP refuses anything else: testbed_nerf.cu lines 2408–2421). Radius 1.5 (nerf_synthetic's box) gives 1, as
    /// NGP's docs recommend for synthetic objects; the cameras may lie outside the cube. Checked at commit abe236e.
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

        /// <summary>nerf_synthetic's ±1.5 box: the scene radius assumed when a dataset says nothing about its size.</summary>
        public const double DefaultSceneRadius = 1.5;

        /// <summary>True for the values instant-ngp accepts: a power of two from 1 to 128.</summary>
        public static bool IsValid(int aabbScale) => aabbScale >= 1 && aabbScale <= Max && (aabbScale & (aabbScale - 1)) == 0;

        /// <summary>
        /// The <c>aabb_scale</c> a transforms file declares, or null when it has none; a value instant-ngp would refuse
        /// (testbed_nerf.cu lines 2408–2421) is a warning and counts as none.
        /// </summary>
        public static int? Declared(JToken value, string file, ICollection<ValidationProblem> warnings = null)
        {
            if (value == null || value.Type == JTokenType.Null) return null;
            if ((value.Type == JTokenType.Integer || value.Type == JTokenType.Float) && (double)value == Math.Floor((double)value)
                && (double)value >= 1 && (double)value <= Max && IsValid((int)(double)value))
                return (int)(double)value;
            warnings?.Add(new ValidationProblem(file + ": aabb_scale", value.ToString(Newtonsoft.Json.Formatting.None),
                "is not a power of two from 1 to 128, which instant-ngp refuses; it is ignored.", "Write 1, 2, 4, … 128, or remove the key."));
            return null;
        }

        /// <summary>
        /// The aabb_scale for a converted dataset: the one its <c>transforms_train.json</c> declares (the capture
        /// computed it from the target), raised — with a warning naming both — when the target's reach recorded in
        /// <c>dataset_config.json</c> needs a larger cube. With neither, nerf_synthetic's box (1).
        /// </summary>
        public static int ForDataset(int? declared, double? targetReach, ICollection<ValidationProblem> warnings = null)
        {
            var needed = targetReach.HasValue ? ForRadius(targetReach.Value, warnings) : (int?)null;
            if (declared == null) return needed ?? ForRadius(DefaultSceneRadius);
            if (needed == null || needed.Value <= declared.Value) return declared.Value;
            warnings?.Add(new ValidationProblem("aabb_scale", declared.Value.ToString(CultureInfo.InvariantCulture),
                $"from transforms_train.json covers only {ValidationProblem.Format(Math.Round(CoveredRadius(declared.Value), 3))} output units, but dataset_config.json says the target reaches {ValidationProblem.Format(Math.Round(targetReach.Value, 3))}; instant-ngp would cut it off, so the export uses {needed.Value}.",
                "Nothing to do for this export; fix aabb_scale in the split files if other tools read them."));
            return needed.Value;
        }
    }
}
