using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A ring: cameras evenly spaced in azimuth at one elevation. The rig distance is the distance to the target
    /// (the original plugin placed halo cameras at √(d² + h²) instead).
    /// </summary>
    [Serializable]
    public sealed class HaloFormation : ICameraFormation, IIndexedFormation
    {
        public HaloFormation(double elevationDegrees = 0, double startAzimuthDegrees = 0)
        {
            ElevationDegrees = elevationDegrees;
            StartAzimuthDegrees = startAzimuthDegrees;
        }

        /// <summary>Elevation of the ring above the target's horizon, strictly between −90 and 90.</summary>
        public double ElevationDegrees { get; }

        /// <summary>Azimuth of the first camera, from Unity's +X towards +Z (counter-clockwise seen from above in the output).</summary>
        public double StartAzimuthDegrees { get; }

        public string Kind => "halo";

        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix) => FormationMath.Collect(fieldPrefix,
            FormationMath.CheckOpenElevation("elevationDegrees", ElevationDegrees),
            ValidationProblem.OutsideRange("startAzimuthDegrees", StartAzimuthDegrees, -360, 360, "degrees"));

        public IReadOnlyList<SphericalDirection> Directions(int count)
        {
            FormationMath.ThrowIfInvalid(this, count);
            var directions = new SphericalDirection[count];
            for (var i = 0; i < count; i++) directions[i] = Direction(i, count);
            return directions;
        }

        /// <summary>Direction <paramref name="index"/> of <paramref name="count"/> alone (a plan regenerates views on demand).</summary>
        public SphericalDirection Direction(int index, int count)
        {
            var elevation = ElevationDegrees * FormationMath.DegToRad;
            var start = StartAzimuthDegrees * FormationMath.DegToRad;
            return new SphericalDirection(FormationMath.WrapRadians(start + 2 * Math.PI * index / count), elevation);
        }
    }
}
