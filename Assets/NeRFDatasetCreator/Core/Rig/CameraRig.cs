using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Places the cameras of a formation around a target at an exact distance, each looking at the target.</summary>
    public static class CameraRig
    {
        public static IReadOnlyList<UnityPose> Place(ICameraFormation formation, int count, Vector3d target, double distance)
        {
            if (formation == null) throw new ArgumentNullException(nameof(formation));
            ThrowIfInvalid(target, distance);
            var directions = formation.Directions(count);
            var poses = new UnityPose[directions.Count];
            for (var i = 0; i < poses.Length; i++)
                poses[i] = LookAt.FromDirection(target, directions[i], distance);
            return poses;
        }

        /// <summary>Throws <see cref="InvalidParameterException"/> unless the target is finite and the distance a finite number above 0.</summary>
        public static void ThrowIfInvalid(Vector3d target, double distance) =>
            InvalidParameterException.ThrowIfAny(
                !(distance > 0) || double.IsInfinity(distance)
                    ? new ValidationProblem("distance", ValidationProblem.Format(distance), "must be a finite number above 0.", "Use the distance from the target to the cameras, in Unity units.")
                    : null,
                target.IsFinite ? null : new ValidationProblem("target", target.ToString(), "is not finite.", "Use a finite target position."));
    }
}
