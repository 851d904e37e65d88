using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One view's exposure: the camera's poses when the shutter opens and closes (Unity world), the matching output
    /// matrices written as <c>transform_matrix_start</c> / <c>_end</c>, and in a dynamic capture the content times at
    /// both ends. The interval is centred on the planned pose: <see cref="At"/>(½) is the view's own pose, whose matrix
    /// stays <c>transform_matrix</c>.
    /// </summary>
    [Serializable]
    public sealed class ShutterMotion
    {
        public ShutterMotion(UnityPose start, UnityPose end, Matrix4x4d startMatrix, Matrix4x4d endMatrix, double? openSeconds, double? closeSeconds)
        {
            Start = start;
            End = end;
            StartMatrix = startMatrix;
            EndMatrix = endMatrix;
            OpenSeconds = openSeconds;
            CloseSeconds = closeSeconds;
        }

        public UnityPose Start { get; }
        public UnityPose End { get; }

        /// <summary>The output camera-to-world matrix when the shutter opens (<c>transform_matrix_start</c>).</summary>
        public Matrix4x4d StartMatrix { get; }

        /// <summary>The output camera-to-world matrix when the shutter closes (<c>transform_matrix_end</c>).</summary>
        public Matrix4x4d EndMatrix { get; }

        /// <summary>Content time when the shutter opens, in seconds; null in a static capture.</summary>
        public double? OpenSeconds { get; }

        /// <summary>Content time when the shutter closes, in seconds; null in a static capture.</summary>
        public double? CloseSeconds { get; }

        /// <summary>The camera pose a fraction <paramref name="t"/> ∈ [0, 1] through the interval (instant-ngp's interpolation).</summary>
        public UnityPose At(double t) => PoseInterpolation.Lerp(Start, End, t);

        /// <summary>The content time a fraction <paramref name="t"/> through the interval; null in a static capture.</summary>
        public double? SecondsAt(double t) => OpenSeconds.HasValue && CloseSeconds.HasValue ? OpenSeconds.Value + (CloseSeconds.Value - OpenSeconds.Value) * t : (double?)null;

        /// <summary>
        /// The interval centred on <paramref name="mid"/> over which the camera moves by <paramref name="translation"/>
        /// (Unity world) and turns by the rotation vector <paramref name="rotation"/> (Unity world, radians):
        /// start = (c − d/2, exp(−ω/2)·R), end = (c + d/2, exp(ω/2)·R).
        /// </summary>
        public static ShutterMotion Centred(UnityPose mid, Vector3d translation, Vector3d rotation, SceneNormalisation normalisation,
            double? openSeconds, double? closeSeconds)
        {
            var half = PoseInterpolation.FromRotationVector(rotation * 0.5);
            var start = new UnityPose(mid.Position - translation * 0.5, (PoseInterpolation.Inverse(half) * mid.Rotation).Normalized());
            var end = new UnityPose(mid.Position + translation * 0.5, (half * mid.Rotation).Normalized());
            return new ShutterMotion(start, end, normalisation.CameraToWorld(start), normalisation.CameraToWorld(end), openSeconds, closeSeconds);
        }
    }
}
