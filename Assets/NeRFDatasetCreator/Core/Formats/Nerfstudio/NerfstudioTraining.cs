using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>ns-train … nerfstudio-data</c> flags that train each nerfstudio model family on our
    /// <c>transforms.json</c> without cutting the target off, from nerfstudio's own code (nerfstudio-project/nerfstudio
    /// at 50e0e3c; file:line below):
    /// <list type="bullet">
    /// <item>Always <c>--orientation-method none --center-method none</c>: the defaults "up" and "poses"
    /// (nerfstudio_dataparser.py:56–58) rotate the world and move the origin to the mean camera
    /// (lines 236–241), away from the target we centred.</item>
    /// <item>nerfacto: positions go through an L∞ scene contraction that leaves only |x|∞ ≤ 1 uncontracted
    /// (models/nerfacto.py:151, fields/nerfacto_field.py:205–208, field_components/spatial_distortions.py:67–69);
    /// the scene box is not used. instant-ngp: the same contraction, and the occupancy grid only marches inside the
    /// scene box (models/instant_ngp.py:103, 114, 120–123), which is ±<c>scene_scale</c> = ±1 (nerfstudio_dataparser.py:54,
    /// 261–265). For both, <c>--auto-scale-poses False --scale-factor f</c> with f ≤ 1/reach puts the whole target in
    /// ±1 without moving it; poses, ply points and depth are all multiplied by that factor (lines 245–249, 452;
    /// data/datasets/depth_dataset.py:119).</item>
    /// <item>splatfacto: Gaussians have no box; its densify/cull thresholds are absolute with scene_scale 1.0
    /// (models/splatfacto.py:267–269, 281), i.e. tuned for nerfstudio's default auto-scaling, which divides every
    /// pose by the largest |coordinate| of any camera (nerfstudio_dataparser.py:245–246). So splatfacto keeps
    /// auto-scaling (its default) and only turns re-orientation and re-centring off; the seed points of
    /// <c>ply_file_path</c> are scaled with the poses (lines 401, 452), and splatfacto loads them by default
    /// (configs/method_configs.py:602, <c>load_3D_points=True</c>).</item>
    /// </list>
    /// </summary>
    public static class NerfstudioTraining
    {
        public static readonly string[] Models = { "nerfacto", "splatfacto", "instant-ngp" };

        /// <summary>nerfacto's uncontracted cube and instant-ngp's default scene box: ±1 after the dataparser's scale.</summary>
        public const double UnitBoxHalfSize = 1;

        public const string KeepFrame = "--orientation-method none --center-method none";

        /// <summary>
        /// The largest factor, rounded down to 3 significant digits, that brings a target reaching
        /// <paramref name="targetReach"/> output units into ±1; 1 when it already fits. Unknown reach counts as
        /// nerf_synthetic's ±1.5 box.
        /// </summary>
        public static double ScaleFactor(double? targetReach)
        {
            var r = targetReach ?? AabbScale.DefaultSceneRadius;
            if (!(r > UnitBoxHalfSize)) return 1;
            var x = UnitBoxHalfSize / r;
            var digits = 2 - (int)Math.Floor(Math.Log10(x));
            var unit = Math.Pow(10, digits);
            var f = Math.Floor(x * unit) / unit;
            return f * r > UnitBoxHalfSize ? (Math.Floor(x * unit) - 1) / unit : f; // guard against x·unit rounding up
        }

        /// <summary>The dataparser flags for one of <see cref="Models"/>.</summary>
        public static string Flags(string model, double? targetReach)
        {
            if (model == "splatfacto") return KeepFrame;
            if (model != "nerfacto" && model != "instant-ngp") throw new ArgumentOutOfRangeException(nameof(model), model, "one of nerfacto, splatfacto, instant-ngp");
            var f = ScaleFactor(targetReach);
            return KeepFrame + " --auto-scale-poses False" +
                   (f < 1 ? " --scale-factor " + f.ToString("0.##########", CultureInfo.InvariantCulture) : "");
        }

        /// <summary>One <c>ns-train</c> line per model for the transforms.json at <paramref name="transformsPath"/>.</summary>
        public static IReadOnlyList<string> Commands(string transformsPath, double? targetReach) =>
            Models.Select(m => "ns-train " + m + " --data " + Quote(transformsPath) + " nerfstudio-data " + Flags(m, targetReach)).ToList();

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;
    }
}
