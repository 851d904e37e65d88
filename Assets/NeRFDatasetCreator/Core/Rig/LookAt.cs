using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Orientations of cameras that look at a target with world +Y up, the same as Unity's
    /// <c>Quaternion.LookRotation(target - position, Vector3.up)</c> wherever that is defined.
    /// </summary>
    public static class LookAt
    {
        /// <summary>
        /// The pose of a camera on <paramref name="direction"/> from <paramref name="target"/> at
        /// <paramref name="distance"/>, looking at the target. Its up vector is the direction of increasing
        /// elevation, ∂d/∂e = (−sin e·cos a, cos e, −sin e·sin a): exactly LookRotation's up away from the poles,
        /// and at the poles the limit along the direction's own azimuth, so the roll there is defined and
        /// continuous with cameras approaching the pole at that azimuth rather than left to chance.
        /// </summary>
        public static UnityPose FromDirection(Vector3d target, SphericalDirection direction, double distance)
        {
            double a = direction.AzimuthRadians, e = direction.ElevationRadians;
            double cosA = Math.Cos(a), sinA = Math.Sin(a), cosE = Math.Cos(e), sinE = Math.Sin(e);
            var outward = new Vector3d(cosE * cosA, sinE, cosE * sinA);
            var forward = -outward;
            var up = new Vector3d(-sinE * cosA, cosE, -sinE * sinA);
            var right = new Vector3d(-sinA, 0, cosA); // up × forward, which stays unit length even at the poles
            return new UnityPose(target + distance * outward, Quaterniond.FromBasis(right, up, forward));
        }

        /// <summary>The pose of a camera at <paramref name="position"/> looking at <paramref name="target"/>.</summary>
        public static UnityPose FromPositions(Vector3d position, Vector3d target)
        {
            var offset = position - target;
            var distance = offset.Length;
            if (!(distance > 0))
                throw new ArgumentException("A camera at its target " + target + " has no direction to look in.", nameof(position));
            var pose = FromDirection(target, SphericalDirection.FromUnityVector(offset), distance);
            return new UnityPose(position, pose.Rotation); // keep the caller's position exactly
        }
    }
}
