using System;
using System.Globalization;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The similarity applied to the whole output world: x_N = s·(x − c), with c the target's centre in the raw
    /// output world (Blender axes, c = P·A_Unity) and s &gt; 0. Camera rotations are unchanged and camera centres move
    /// like every other point, so each camera sees the target exactly as before (pinhole projection is invariant
    /// under a uniform scale of scene and cameras together). Depth is a distance and scales by s alone:
    /// depth_N = s · metric z (see <see cref="ApplyToDepth"/>).
    /// </summary>
    public sealed class SceneNormalisation
    {
        public SceneNormalisation(Vector3d centre, double scale)
        {
            InvalidParameterException.ThrowIfAny(
                centre.IsFinite ? null : new ValidationProblem("normalisation.centre", centre.ToString(), "is not a finite point.", "Use the target's bounding-box centre."),
                scale > 0 && !double.IsInfinity(scale) ? null : ValidationProblem.OutsideRange("normalisation.scale", scale, 1e-9, 1e9));
            Centre = centre;
            Scale = scale;
        }

        public static SceneNormalisation Identity => new SceneNormalisation(Vector3d.Zero, 1);

        /// <summary>Centre c in the raw output world (before scaling); it becomes the origin.</summary>
        public Vector3d Centre { get; }

        /// <summary>Scale s: output units per raw (Unity) unit.</summary>
        public double Scale { get; }

        /// <summary>NeRF's Blender loaders (bmild/nerf, nerf-pytorch) hard-code near 2 and far 6.</summary>
        public const double NerfNear = 2;
        public const double NerfFar = 6;

        /// <summary>nerf_synthetic's camera radius (test r_0 is 4.03 from the origin).</summary>
        public const double NerfSyntheticCameraRadius = 4;

        /// <summary>Largest target radius for which the preset keeps every loader's constraint: b ≤ 0.325·R (§2.4: s·b ≤ 1.3 with s = 4/R).</summary>
        public const double PresetMaxTargetRadiusFraction = 0.325;

        /// <summary>3DGS's random initial cloud fills [−1.3, 1.3]³.</summary>
        public const double GaussianSplattingInitHalfSize = 1.3;

        /// <summary>
        /// The normalisation for a target centred at <paramref name="targetCentreUnity"/> (Unity world) with bounding
        /// sphere radius <paramref name="targetRadius"/> (Unity units), photographed from a mean distance
        /// <paramref name="meanCameraDistance"/>. <paramref name="chosenRadius"/> is the output radius of the target
        /// for <see cref="NormalisationMode.FitTargetRadius"/>.
        /// </summary>
        public static SceneNormalisation ForTarget(NormalisationMode mode, Vector3d targetCentreUnity, double targetRadius,
            double meanCameraDistance, double chosenRadius = GaussianSplattingInitHalfSize)
        {
            InvalidParameterException.ThrowIfAny(
                targetCentreUnity.IsFinite ? null : new ValidationProblem("normalisation.targetCentre", targetCentreUnity.ToString(), "is not a finite point.", "Pick a target object with finite bounds."),
                mode == NormalisationMode.FitTargetRadius ? ValidationProblem.OutsideRange("normalisation.targetRadius", targetRadius, 1e-9, 1e9) : null,
                mode == NormalisationMode.FitTargetRadius ? ValidationProblem.OutsideRange("normalisation.chosenRadius", chosenRadius, 1e-9, 1e9) : null,
                mode == NormalisationMode.NerfSyntheticScale ? ValidationProblem.OutsideRange("normalisation.meanCameraDistance", meanCameraDistance, 1e-9, 1e9) : null);
            var centre = BlenderConvention.FromUnity(targetCentreUnity);
            switch (mode)
            {
                case NormalisationMode.None: return Identity;
                case NormalisationMode.Recentre: return new SceneNormalisation(centre, 1);
                case NormalisationMode.NerfSyntheticScale: return new SceneNormalisation(centre, NerfSyntheticCameraRadius / meanCameraDistance);
                case NormalisationMode.FitTargetRadius: return new SceneNormalisation(centre, chosenRadius / targetRadius);
                default: throw new ArgumentOutOfRangeException(nameof(mode), mode, "Unknown normalisation mode.");
            }
        }

        /// <summary>A raw output-world point (Blender axes) into the normalised world.</summary>
        public Vector3d ApplyToPoint(Vector3d rawOutputPoint) => (rawOutputPoint - Centre) * Scale;

        /// <summary>A Unity world point straight into the normalised output world.</summary>
        public Vector3d ApplyToUnityPoint(Vector3d unityPoint) => ApplyToPoint(BlenderConvention.FromUnity(unityPoint));

        /// <summary>
        /// A Unity camera pose as its normalised output c2w: the same matrix as
        /// <c>ApplyToCameraToWorld(BlenderConvention.CameraToWorld(pose))</c> without the matrix in between (the plan makes one per view).
        /// </summary>
        public Matrix4x4d CameraToWorld(UnityPose pose)
        {
            var rotation = pose.Rotation;
            return Matrix4x4d.FromColumns(BlenderConvention.FromUnity(rotation.Right), BlenderConvention.FromUnity(rotation.Up),
                -BlenderConvention.FromUnity(rotation.Forward), ApplyToUnityPoint(pose.Position));
        }

        /// <summary>A raw output c2w into the normalised world: same rotation, moved centre.</summary>
        public Matrix4x4d ApplyToCameraToWorld(Matrix4x4d rawCameraToWorld) => Matrix4x4d.FromColumns(
            rawCameraToWorld.Column(0), rawCameraToWorld.Column(1), rawCameraToWorld.Column(2),
            ApplyToPoint(rawCameraToWorld.Translation));

        /// <summary>
        /// A metric z-depth (Unity units along the camera axis) in output units: z·s. Depth is a length, so the
        /// recentring does not touch it; every depth file of a normalised dataset must be written through this.
        /// </summary>
        public double ApplyToDepth(double metricDepth) => metricDepth * Scale;

        /// <summary>The 4×4 matrix of the similarity, x_N = M·x: [s·I | −s·c].</summary>
        public Matrix4x4d Matrix => Matrix4x4d.FromColumns(
            new Vector3d(Scale, 0, 0), new Vector3d(0, Scale, 0), new Vector3d(0, 0, Scale), -Scale * Centre);

        /// <summary>The record written into exported JSON files and dataset_config.json under <c>scene_normalisation</c>.</summary>
        public JObject ToJson() => new JObject
        {
            ["scale"] = Scale,
            ["centre"] = new JArray(Centre.X, Centre.Y, Centre.Z),
            ["transform"] = ExportJson.Matrix(Matrix),
            ["meaning"] = "x_out = scale * (x_blender - centre), x_blender = (x, z, y) of the Unity world point; depth_out = scale * metric z",
        };

        /// <summary>Reads a record written by <see cref="ToJson"/>.</summary>
        public static SceneNormalisation FromJson(JToken token)
        {
            bool IsNumber(JToken t) => JsonValues.TryNumber(t, out _);
            double Number(JToken t) => JsonValues.TryNumber(t, out var v) ? v : 0;
            if (!(token is JObject o) || !IsNumber(o["scale"]) || !(o["centre"] is JArray c) || c.Count != 3 || !c.All(IsNumber))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("scene_normalisation", token?.ToString(Newtonsoft.Json.Formatting.None) ?? "null",
                        "is not a record with a number \"scale\" and a \"centre\" of 3 numbers.", "Remove the key or restore it from the original export."),
                });
            return new SceneNormalisation(new Vector3d(Number(c[0]), Number(c[1]), Number(c[2])), Number(o["scale"]));
        }

        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "x_out = {0:R}·(x − {1})", Scale, Centre);
    }
}
