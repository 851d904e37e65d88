using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Golden-ratio sampling of a band of elevations — by default the upper hemisphere. Heights sin e run
    /// area-uniformly from the top of the band to its bottom at (i + ½)/N, and the azimuth advances by
    /// 2π·<see cref="SpiralRatio"/> per camera. This keeps the original plugin's advanced parameters in a form one
    /// can read: its "top" c₁ and "bottom" span c₂ become elevations in degrees (see <see cref="FromLegacy"/>), and
    /// its ratio stays: 0 means the golden ratio (an even spiral), a fraction k/m gives m vertical columns, a value
    /// near a whole number a slowly winding helix.
    /// </summary>
    [Serializable]
    public sealed class SemiSphereFormation : ICameraFormation, IIndexedFormation
    {
        public SemiSphereFormation(double topElevationDegrees = 90, double bottomElevationDegrees = 0, double spiralRatio = 0)
        {
            TopElevationDegrees = topElevationDegrees;
            BottomElevationDegrees = bottomElevationDegrees;
            SpiralRatio = spiralRatio;
        }

        /// <summary>Upper edge of the band, −90…90 degrees (90 = straight above the target).</summary>
        public double TopElevationDegrees { get; }

        /// <summary>Lower edge of the band, −90…<see cref="TopElevationDegrees"/> (0 = level with the target).</summary>
        public double BottomElevationDegrees { get; }

        /// <summary>Azimuth turns per camera; 0 selects the golden ratio φ. Only the fractional part matters.</summary>
        public double SpiralRatio { get; }

        public string Kind => "semisphere";

        /// <summary>
        /// The formation the original plugin drew for its parameters p1 ("top", a height in [−1, 1]), p2 ("bottom",
        /// actually the span of heights) and p3 (ratio, 0 = golden). Its heights ran from p1 to about p1 − p2.
        /// </summary>
        public static SemiSphereFormation FromLegacy(double top, double span, double ratio)
        {
            InvalidParameterException.ThrowIfAny(
                ValidationProblem.OutsideRange("top", top, -1, 1),
                ValidationProblem.OutsideRange("span", span, 0, 1 + top));
            var degrees = 180.0 / Math.PI;
            return new SemiSphereFormation(FormationMath.SafeAsin(top) * degrees, FormationMath.SafeAsin(top - span) * degrees, ratio);
        }

        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix)
        {
            var top = ValidationProblem.OutsideRange("topElevationDegrees", TopElevationDegrees, -90, 90, "degrees");
            var bottom = ValidationProblem.OutsideRange("bottomElevationDegrees", BottomElevationDegrees, -90, 90, "degrees");
            if (top == null && bottom == null && BottomElevationDegrees > TopElevationDegrees)
                bottom = new ValidationProblem("bottomElevationDegrees", ValidationProblem.Format(BottomElevationDegrees),
                    "is above topElevationDegrees (" + ValidationProblem.Format(TopElevationDegrees) + ").",
                    "Make the bottom of the band lower than or equal to its top.");
            if (top == null && bottom == null && BottomElevationDegrees == TopElevationDegrees && Math.Abs(TopElevationDegrees) == 90)
                bottom = new ValidationProblem("bottomElevationDegrees", ValidationProblem.Format(BottomElevationDegrees),
                    "makes the band a single point on the pole, where every camera would stand on the same spot.",
                    "Lower the bottom of the band (or raise it, at the south pole).");
            return FormationMath.Collect(fieldPrefix, top, bottom,
                ValidationProblem.OutsideRange("spiralRatio", SpiralRatio, 0, 1000));
        }

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
            var topHeight = Math.Sin(TopElevationDegrees * FormationMath.DegToRad);
            var bottomHeight = Math.Sin(BottomElevationDegrees * FormationMath.DegToRad);
            var ratio = SpiralRatio == 0 ? FormationMath.GoldenRatio : SpiralRatio;
            var height = topHeight - (topHeight - bottomHeight) * (index + 0.5) / count;
            // Only the fractional part of ratio·i turns the camera; reducing it first keeps precision for large i.
            var turns = ratio * index;
            turns -= Math.Floor(turns);
            return new SphericalDirection(FormationMath.WrapRadians(2 * Math.PI * turns), FormationMath.SafeAsin(height));
        }
    }
}
