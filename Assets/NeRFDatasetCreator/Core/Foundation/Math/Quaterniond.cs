using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A double-precision rotation quaternion with Unity's semantics: (X, Y, Z, W) storage, Hamilton product,
    /// <see cref="Rotate"/> = q·v·q⁻¹, and <see cref="LookRotation"/> building the same basis as
    /// <c>Quaternion.LookRotation</c> (rotated +Z = forward, rotated +Y = up made orthogonal to forward).
    /// Unity's quaternion maths is the standard one; only its world is left-handed.
    /// </summary>
    [Serializable]
    public readonly struct Quaterniond : IEquatable<Quaterniond>
    {
        public readonly double X;
        public readonly double Y;
        public readonly double Z;
        public readonly double W;

        public Quaterniond(double x, double y, double z, double w)
        {
            X = x;
            Y = y;
            Z = z;
            W = w;
        }

        public static readonly Quaterniond Identity = new Quaterniond(0, 0, 0, 1);

        public static Quaterniond operator *(Quaterniond a, Quaterniond b) => new Quaterniond(
            a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
            a.W * b.Y + a.Y * b.W + a.Z * b.X - a.X * b.Z,
            a.W * b.Z + a.Z * b.W + a.X * b.Y - a.Y * b.X,
            a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z);

        /// <summary>The vector rotated by this (unit) quaternion, like Unity's <c>rotation * vector</c>.</summary>
        public Vector3d Rotate(Vector3d v)
        {
            // v' = v + w·t + q×t with t = 2(q×v), the expansion of q·v·q* for a unit quaternion — written out in
            // scalars, operation for operation as Vector3d.Cross and its operators compute it (the same bits), because
            // Mono inlines none of those calls and a plan rotates three axes for each of up to 300 000 views.
            double x = X, y = Y, z = Z, w = W, vx = v.X, vy = v.Y, vz = v.Z;
            double tx = (y * vz - z * vy) * 2.0, ty = (z * vx - x * vz) * 2.0, tz = (x * vy - y * vx) * 2.0;
            return new Vector3d(vx + tx * w + (y * tz - z * ty), vy + ty * w + (z * tx - x * tz), vz + tz * w + (x * ty - y * tx));
        }

        public Vector3d Right => Rotate(Vector3d.UnitX);
        public Vector3d Up => Rotate(Vector3d.UnitY);
        public Vector3d Forward => Rotate(Vector3d.UnitZ);

        public double Norm => Math.Sqrt(X * X + Y * Y + Z * Z + W * W);

        public Quaterniond Normalized()
        {
            var n = Norm;
            return new Quaterniond(X / n, Y / n, Z / n, W / n);
        }

        /// <summary>Rotation by <paramref name="degrees"/> about <paramref name="axis"/>, as Unity's <c>Quaternion.AngleAxis</c>.</summary>
        public static Quaterniond AngleAxis(double degrees, Vector3d axis)
        {
            var half = degrees * Math.PI / 360.0;
            var a = axis.Normalized() * Math.Sin(half);
            return new Quaterniond(a.X, a.Y, a.Z, Math.Cos(half));
        }

        /// <summary>
        /// The rotation whose +Z is <paramref name="forward"/> and whose +Y is <paramref name="up"/> made orthogonal
        /// to it: right = normalise(up × forward), up' = forward × right — the basis of Unity's
        /// <c>Quaternion.LookRotation</c>. Throws when the vectors are parallel or zero, where Unity's result is
        /// arbitrary; callers pick a defined up instead (see <see cref="LookAt"/>).
        /// </summary>
        public static Quaterniond LookRotation(Vector3d forward, Vector3d up)
        {
            var f = forward.Normalized();
            var rightUnnormalised = Vector3d.Cross(up, f);
            if (!(rightUnnormalised.Length > 1e-12 * up.Length))
                throw new ArgumentException("LookRotation: up " + up + " is parallel to forward " + forward + "; the roll would be undefined.");
            var r = rightUnnormalised.Normalized();
            var u = Vector3d.Cross(f, r);
            return FromBasis(r, u, f);
        }

        /// <summary>The rotation taking the unit axes X, Y, Z to the orthonormal, right-handed-by-formula columns r, u, f.</summary>
        public static Quaterniond FromBasis(Vector3d r, Vector3d u, Vector3d f)
        {
            // Shepperd's method on the matrix with columns (r, u, f): stable for every rotation.
            double m00 = r.X, m10 = r.Y, m20 = r.Z;
            double m01 = u.X, m11 = u.Y, m21 = u.Z;
            double m02 = f.X, m12 = f.Y, m22 = f.Z;
            var trace = m00 + m11 + m22;
            Quaterniond q;
            if (trace > 0)
            {
                var s = Math.Sqrt(trace + 1.0) * 2;
                q = new Quaterniond((m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s);
            }
            else if (m00 > m11 && m00 > m22)
            {
                var s = Math.Sqrt(1.0 + m00 - m11 - m22) * 2;
                q = new Quaterniond(0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s);
            }
            else if (m11 > m22)
            {
                var s = Math.Sqrt(1.0 + m11 - m00 - m22) * 2;
                q = new Quaterniond((m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s);
            }
            else
            {
                var s = Math.Sqrt(1.0 + m22 - m00 - m11) * 2;
                q = new Quaterniond((m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s);
            }
            q = q.Normalized();
            // One canonical sign (w ≥ 0) so that equal rotations serialise identically.
            return q.W < 0 ? new Quaterniond(-q.X, -q.Y, -q.Z, -q.W) : q;
        }

        public bool Equals(Quaterniond other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z) && W.Equals(other.W);
        public override bool Equals(object obj) => obj is Quaterniond other && Equals(other);
        public override int GetHashCode() => HashCode.Combine(X, Y, Z, W);

        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "({0:R}, {1:R}, {2:R}, {3:R})", X, Y, Z, W);
    }
}
