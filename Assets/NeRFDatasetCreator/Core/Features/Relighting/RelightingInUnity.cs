using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One relighting render as the Unity Editor sets it up (issue 38): the file key, and the condition's light in
    /// Unity's world. Engine-free; made by <see cref="RelightingInUnity.Resolve"/>.
    /// </summary>
    public sealed class UnityLightingRender
    {
        /// <summary>The file key: the name for point / spot, <c>name_rot</c> (3-digit degrees) for an environment.</summary>
        public string Key { get; internal set; }
        public LightingKind Kind { get; internal set; }

        /// <summary>Environment: the project path of the texture (cubemap or equirect).</summary>
        public string File { get; internal set; }

        /// <summary>Environment: the rotation in the output frame (degrees, counter-clockwise about +Z seen from above).</summary>
        public double OutputRotationDegrees { get; internal set; }

        /// <summary>Environment: the skybox material's <c>_Rotation</c> that gives it (<see cref="RelightingInUnity.SkyboxRotationDegrees"/>).</summary>
        public double SkyboxRotationDegrees { get; internal set; }

        public double Intensity { get; internal set; }

        /// <summary>Point / spot: the light's position in Unity's world.</summary>
        public Vector3d Position { get; internal set; }

        /// <summary>Spot: the unit direction it points in Unity's world.</summary>
        public Vector3d Direction { get; internal set; }
        public double SpotAngle { get; internal set; }
        public double[] Colour { get; internal set; }
        public bool Shadows { get; internal set; }
    }

    /// <summary>
    /// The relighting conditions in Unity's terms. Positions and directions are given in the OUTPUT world (Blender's
    /// frame, +Z up, normalised units) and go back into Unity's world through the dataset's own <c>unity_frame</c>
    /// matrix (<see cref="UnityFrameRecord.Matrix"/>: x_unity = M·[x_out, 1]). An environment rotation θ about the
    /// output +Z is the skybox <c>_Rotation</c> θ: Unity's Skybox/Panoramic and Skybox/Cubemap shaders move the sky
    /// mesh's vertex t to R(φ)·t with R(φ) = [[cos φ, −sin φ], [sin φ, cos φ]] acting on (x, z) and sample the texture at
    /// t (Skybox-Panoramic.shader <c>RotateAroundYInDegrees</c> and <c>vert</c>: <c>o.texcoord = v.vertex.xyz</c>), so
    /// light that arrived from t arrives from R(φ)·t; the output frame's (x, y) are Unity's (x, z)
    /// (<see cref="BlenderConvention"/>) and normalisation only scales and shifts, so R(φ) on Unity's (x, z) is Rz(φ) on
    /// the output's (x, y): counter-clockwise about +Z seen from above, by the same angle.
    /// </summary>
    public static class RelightingInUnity
    {
        /// <summary>The skybox <c>_Rotation</c> (in [0, 360)) for an output-frame rotation θ (see the class summary).</summary>
        public static double SkyboxRotationDegrees(double outputDegrees) => UnitySkybox.ToUnityRotation(outputDegrees);

        /// <summary>The file key of one render: <c>name</c>, or <c>name_DDD</c> for an environment at DDD degrees.</summary>
        public static string Key(LightingCondition condition, double rotation) =>
            condition.Kind == LightingKind.Environment ? LightingKeys.Environment(condition.Name, rotation) : condition.Name;

        /// <summary>Every render of the settings, in order: each environment at each rotation, each point / spot once.</summary>
        public static List<UnityLightingRender> Resolve(RelightingSettings settings, SceneNormalisation normalisation)
        {
            var renders = new List<UnityLightingRender>();
            if (settings == null || !settings.Enabled) return renders;
            var frame = UnityFrameRecord.Matrix(normalisation ?? SceneNormalisation.Identity);
            foreach (var c in settings.Conditions)
            {
                if (c == null) continue;
                if (c.Kind == LightingKind.Environment)
                {
                    foreach (var rotation in c.Rotations ?? new double[] { 0 })
                        renders.Add(new UnityLightingRender
                        {
                            Key = Key(c, rotation), Kind = c.Kind, File = c.File, OutputRotationDegrees = rotation,
                            SkyboxRotationDegrees = SkyboxRotationDegrees(rotation), Intensity = c.Intensity,
                        });
                    continue;
                }
                var position = Vector(c.Position, new Vector3d(0, 0, 4));
                // A spot without a direction points at the output origin (LightingCondition.Direction's default).
                var direction = c.Direction != null && c.Direction.Length == 3 ? Vector(c.Direction, Vector3d.Zero) : -position;
                var unityDirection = frame.MultiplyVector(direction);
                var length = unityDirection.Length;
                renders.Add(new UnityLightingRender
                {
                    Key = Key(c, 0), Kind = c.Kind, Intensity = c.Intensity, SpotAngle = c.SpotAngle,
                    Position = frame.MultiplyPoint(position),
                    Direction = length > 0 ? unityDirection / length : new Vector3d(0, -1, 0),
                    Colour = c.Colour != null && c.Colour.Length == 3 ? (double[])c.Colour.Clone() : new double[] { 1, 1, 1 },
                    Shadows = c.Shadows,
                });
            }
            return renders;
        }

        static Vector3d Vector(double[] v, Vector3d fallback) => v != null && v.Length == 3 ? new Vector3d(v[0], v[1], v[2]) : fallback;
    }
}
