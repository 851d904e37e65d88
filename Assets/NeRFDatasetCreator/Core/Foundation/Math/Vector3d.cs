using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A double-precision 3-vector. Core computes in double so that written poses keep full precision; the Unity
    /// layer converts to and from <c>Vector3</c> only at the boundary. The components carry no handedness: the
    /// frame (Unity's left-handed Y-up world or the Blender/OpenGL output world) is given by the caller.
    /// </summary>
    [Serializable]
    public readonly struct Vector3d : IEquatable<Vector3d>
    {
        public readonly double X;
        public readonly double Y;
        public readonly double Z;

        public Vector3d(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        public static readonly Vector3d Zero = new Vector3d(0, 0, 0);
        public static readonly Vector3d UnitX = new Vector3d(1, 0, 0);
        public static readonly Vector3d UnitY = new Vector3d(0, 1, 0);
        public static readonly Vector3d UnitZ = new Vector3d(0, 0, 1);

        public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);
        public double LengthSquared => X * X + Y * Y + Z * Z;
        public bool IsFinite => IsFiniteNumber(X) && IsFiniteNumber(Y) && IsFiniteNumber(Z);

        /// <summary>This vector scaled to unit length. Throws for a zero or non-finite vector, which has no direction.</summary>
        public Vector3d Normalized()
        {
            var length = Length;
            if (!(length > 0) || double.IsInfinity(length))
                throw new InvalidOperationException("Cannot normalise the vector " + this + ": it has no direction.");
            return this / length;
        }

        public static double Dot(Vector3d a, Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>The standard cross product formula (the same one Unity's <c>Vector3.Cross</c> uses).</summary>
        public static Vector3d Cross(Vector3d a, Vector3d b) =>
            new Vector3d(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        public static double Distance(Vector3d a, Vector3d b) => (a - b).Length;

        /// <summary>The angle between two non-zero vectors, in radians, accurate also for nearly parallel vectors.</summary>
        public static double AngleBetween(Vector3d a, Vector3d b) => Math.Atan2(Cross(a, b).Length, Dot(a, b));

        public static Vector3d operator +(Vector3d a, Vector3d b) => new Vector3d(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Vector3d operator -(Vector3d a, Vector3d b) => new Vector3d(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Vector3d operator -(Vector3d a) => new Vector3d(-a.X, -a.Y, -a.Z);
        public static Vector3d operator *(Vector3d a, double s) => new Vector3d(a.X * s, a.Y * s, a.Z * s);
        public static Vector3d operator *(double s, Vector3d a) => new Vector3d(a.X * s, a.Y * s, a.Z * s);
        public static Vector3d operator /(Vector3d a, double s) => new Vector3d(a.X / s, a.Y / s, a.Z / s);

        public bool Equals(Vector3d other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z);
        public override bool Equals(object obj) => obj is Vector3d other && Equals(other);
        public override int GetHashCode() => HashCode.Combine(X, Y, Z);
        public static bool operator ==(Vector3d a, Vector3d b) => a.Equals(b);
        public static bool operator !=(Vector3d a, Vector3d b) => !a.Equals(b);

        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "({0:R}, {1:R}, {2:R})", X, Y, Z);

        static bool IsFiniteNumber(double value) => !double.IsNaN(value) && !double.IsInfinity(value);
    }
}
