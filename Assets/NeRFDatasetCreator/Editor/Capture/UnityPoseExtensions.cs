using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>The boundary between Core's double-precision poses and Unity's float transforms.</summary>
    public static class UnityPoseExtensions
    {
        public static Vector3 ToVector3(this Vector3d v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);

        public static Quaternion ToQuaternion(this Quaterniond q)
        {
            // Normalised in double first: float rounding of an unnormalised input would be amplified by Unity.
            var n = q.Normalized();
            return new Quaternion((float)n.X, (float)n.Y, (float)n.Z, (float)n.W);
        }

        /// <summary>Places <paramref name="transform"/> (unit scale, no parent) at <paramref name="pose"/>.</summary>
        public static void ApplyTo(this UnityPose pose, Transform transform)
        {
            transform.SetPositionAndRotation(pose.Position.ToVector3(), pose.Rotation.ToQuaternion());
        }
    }
}
