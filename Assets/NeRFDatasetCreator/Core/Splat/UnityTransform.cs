using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A 4×4 as a Unity Transform shows it: M = T·R·S (Unity's <c>Matrix4x4.TRS</c>), the scale the columns' lengths and
    /// a reflection (negative determinant) carried by the z scale alone, as the contract asks. Exact for the
    /// maps placement composes (similarities: orthogonal columns); <see cref="Shear"/> says how far a matrix is from one.
    /// </summary>
    public sealed class UnityTransform
    {
        UnityTransform(Vector3d position, Quaterniond rotation, Vector3d scale, double shear)
        {
            Position = position;
            Rotation = rotation;
            Scale = scale;
            Shear = shear;
        }

        public Vector3d Position { get; }

        /// <summary>Transform.rotation (x, y, z, w), w ≥ 0.</summary>
        public Quaterniond Rotation { get; }

        /// <summary>Transform.localScale; z negative when the map reflects.</summary>
        public Vector3d Scale { get; }

        /// <summary>The largest |cosine| between two columns: 0 for the similarities placement composes.</summary>
        public double Shear { get; }

        public static UnityTransform FromMatrix(Matrix4x4d m)
        {
            Vector3d c0 = m.Column(0), c1 = m.Column(1), c2 = m.Column(2);
            double sx = c0.Length, sy = c1.Length, sz = c2.Length;
            if (!(sx > 0 && sy > 0 && sz > 0)) throw new ArgumentException("A Transform cannot show a matrix with a zero column.", nameof(m));
            if (m.Determinant3x3 < 0) sz = -sz;
            var shear = Math.Max(Math.Abs(Vector3d.Dot(c0, c1)) / Math.Abs(sx * sy), Math.Max(Math.Abs(Vector3d.Dot(c0, c2)) / Math.Abs(sx * sz), Math.Abs(Vector3d.Dot(c1, c2)) / Math.Abs(sy * sz)));
            var rotation = Quaterniond.FromBasis(c0 / sx, c1 / sy, c2 / sz);
            return new UnityTransform(m.Translation, rotation, new Vector3d(sx, sy, sz), shear);
        }

        /// <summary>T·R·S again, for checks.</summary>
        public Matrix4x4d ToMatrix() => Matrix4x4d.FromColumns(Rotation.Rotate(Vector3d.UnitX) * Scale.X, Rotation.Rotate(Vector3d.UnitY) * Scale.Y,
            Rotation.Rotate(Vector3d.UnitZ) * Scale.Z, Position);

        /// <summary>
        /// The rotation as the Inspector's Euler angles in degrees: Unity applies z, then x, then y (R = Ry·Rx·Rz,
        /// <c>Transform.eulerAngles</c>' documented order); each in (−180, 180].
        /// </summary>
        public Vector3d EulerDegrees
        {
            get
            {
                var r = Matrix4x4d.FromColumns(Rotation.Rotate(Vector3d.UnitX), Rotation.Rotate(Vector3d.UnitY), Rotation.Rotate(Vector3d.UnitZ), Vector3d.Zero);
                var sinX = Math.Max(-1, Math.Min(1, -r[1, 2]));
                double x = Math.Asin(sinX), y, z;
                if (Math.Abs(sinX) < 1 - 1e-12)
                {
                    y = Math.Atan2(r[0, 2], r[2, 2]);
                    z = Math.Atan2(r[1, 0], r[1, 1]);
                }
                else
                {
                    // Gimbal lock (x = ±90°): only y ∓ z is defined; Unity's Inspector then shows z = 0.
                    y = Math.Atan2(-r[2, 0], r[0, 0]);
                    z = 0;
                }
                return new Vector3d(Degrees(x), Degrees(y), Degrees(z));
            }
        }

        static double Degrees(double radians)
        {
            var d = radians * 180 / Math.PI;
            d = Math.Round(d, 9); // 90.00000000000001 shows as 90
            return d <= -180 ? d + 360 : d == 0 ? 0 : d;
        }
    }
}
