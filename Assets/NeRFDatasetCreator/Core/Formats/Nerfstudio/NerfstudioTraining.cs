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
    /// An inside-out environment capture (<see cref="EnvironmentFlags"/>) wants the opposite of a target in ±1: the
    /// cameras' volume is the uncontracted region and everything beyond is contracted.
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

        /// <summary>
        /// nerfacto's and instant-ngp's scene contraction, stated on the command line (nerfstudio's tyro config takes
        /// <c>True</c>/<c>False</c> values: FlagConversionOff, configs/method_configs.py:808). It is on by default
        /// (models/nerfacto.py:121, 148–151; models/instant_ngp.py:79, 100–103): an environment must keep it.
        /// </summary>
        public const string KeepContraction = "--pipeline.model.disable-scene-contraction False";

        /// <summary>
        /// The dataparser's own centring and scaling, without its re-orientation (our +Z is already up): the origin
        /// moves to the mean camera (<c>--center-method poses</c>: cameras/camera_utils.py:552, 593,
        /// <c>translation = mean_origin</c>) and every pose is divided by the largest |coordinate| of any camera
        /// (<c>--auto-scale-poses True</c>, nerfstudio_dataparser.py:244–249), so the capture volume fills ±1 — the
        /// region nerfacto's L∞ contraction leaves linear — and the rest of the scene is contracted into ±2
        /// (field_components/spatial_distortions.py:42–69; fields/nerfacto_field.py:205–208).
        /// </summary>
        public const string CentreOnCameras = "--orientation-method none --center-method poses --auto-scale-poses True";

        /// <summary>
        /// The flags for one of <see cref="Models"/> on an inside-out capture whose cameras stand at
        /// <paramref name="cameraPositions"/> (output frame) in an environment reaching <paramref name="environmentReach"/>
        /// output units from the origin (null: unknown). instant-ngp also gets <c>--scene-scale</c>: its occupancy grid
        /// only marches inside the scene box ±scene_scale (models/instant_ngp.py:114–123; nerfstudio_dataparser.py:54,
        /// 261–266), which must hold the environment after the dataparser's scaling. splatfacto has no contraction and
        /// keeps the same centring and scaling (its thresholds assume auto-scaling, models/splatfacto.py:281).
        /// </summary>
        public static string EnvironmentFlags(string model, IReadOnlyList<Vector3d> cameraPositions, double? environmentReach)
        {
            if (model == "nerfacto" || model == "splatfacto") return CentreOnCameras;
            if (model != "instant-ngp") throw new ArgumentOutOfRangeException(nameof(model), model, "one of nerfacto, splatfacto, instant-ngp");
            var box = EnvironmentSceneScale(cameraPositions, environmentReach);
            return CentreOnCameras + (box > 1 ? " --scene-scale " + box.ToString("0.##########", CultureInfo.InvariantCulture) : "");
        }

        /// <summary>
        /// The dataparser's factor for <c>--center-method poses --auto-scale-poses True</c>: 1 / the largest |coordinate|
        /// of a camera centre after the mean centre is subtracted (nerfstudio_dataparser.py:245–246); 1 for a single
        /// position.
        /// </summary>
        public static double AutoScale(IReadOnlyList<Vector3d> cameraPositions)
        {
            if (cameraPositions == null || cameraPositions.Count == 0) return 1;
            var mean = MeanOf(cameraPositions);
            var reach = cameraPositions.Max(p => Math.Max(Math.Abs(p.X - mean.X), Math.Max(Math.Abs(p.Y - mean.Y), Math.Abs(p.Z - mean.Z))));
            return reach > 0 ? 1 / reach : 1;
        }

        /// <summary>
        /// instant-ngp's scene box half-size for an environment: its reach from the mean camera (at most reach + |mean|)
        /// times <see cref="AutoScale"/>, rounded up to 2 significant digits; at least 1, nerfstudio's default. An unknown
        /// reach keeps 1.
        /// </summary>
        public static double EnvironmentSceneScale(IReadOnlyList<Vector3d> cameraPositions, double? environmentReach)
        {
            if (environmentReach == null || cameraPositions == null || cameraPositions.Count == 0) return 1;
            var r = (environmentReach.Value + MeanOf(cameraPositions).Length) * AutoScale(cameraPositions);
            if (!(r > 1) || double.IsInfinity(r)) return 1;
            var unit = Math.Pow(10, Math.Floor(Math.Log10(r)) - 1);
            return Math.Ceiling(r / unit - 1e-9) * unit;
        }

        /// <summary>
        /// The <c>ns-train</c> lines for an inside-out environment: the model's contraction flag before the dataparser
        /// subcommand for nerfacto and instant-ngp, <see cref="EnvironmentFlags"/> after it.
        /// </summary>
        public static IReadOnlyList<string> EnvironmentCommands(string transformsPath, IReadOnlyList<Vector3d> cameraPositions, double? environmentReach) =>
            Models.Select(m => "ns-train " + m + (m == "splatfacto" ? "" : " " + KeepContraction) + " --data " + Quote(transformsPath) +
                               " nerfstudio-data " + EnvironmentFlags(m, cameraPositions, environmentReach)).ToList();

        static Vector3d MeanOf(IReadOnlyList<Vector3d> points)
        {
            var sum = Vector3d.Zero;
            foreach (var p in points) sum = sum + p;
            return sum / points.Count;
        }

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;
    }
}
