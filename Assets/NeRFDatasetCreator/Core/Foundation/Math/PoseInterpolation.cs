using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Interpolation between two camera poses as instant-ngp does it for motion blur and rolling shutter
    /// (<c>camera_slerp</c>, include/neural-graphics-primitives/common_device.cuh: rotation slerped, position mixed
    /// linearly): so a pose between a frame's <c>transform_matrix_start</c> and <c>_end</c> is the one its trainer uses.
    /// Rotations stay proper (det +1): the result is a unit quaternion.
    /// </summary>
    public static class PoseInterpolation
    {
        /// <summary>The rotation a fraction <paramref name="t"/> of the way from <paramref name="a"/> to <paramref name="b"/>, along the shorter arc.</summary>
        public static Quaterniond Slerp(Quaterniond a, Quaterniond b, double t)
        {
            var dot = a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
            if (dot < 0)
            {
                // q and −q are the same rotation: take the one on a's side, so the arc is the shorter one.
                b = new Quaterniond(-b.X, -b.Y, -b.Z, -b.W);
                dot = -dot;
            }
            double wa, wb;
            if (dot > 1 - 1e-12)
            {
                wa = 1 - t;
                wb = t;
            }
            else
            {
                var theta = Math.Acos(Math.Min(1, dot));
                var sin = Math.Sin(theta);
                wa = Math.Sin((1 - t) * theta) / sin;
                wb = Math.Sin(t * theta) / sin;
            }
            return new Quaterniond(wa * a.X + wb * b.X, wa * a.Y + wb * b.Y, wa * a.Z + wb * b.Z, wa * a.W + wb * b.W).Normalized();
        }

        /// <summary>The pose a fraction <paramref name="t"/> from <paramref name="a"/> to <paramref name="b"/>: position linear, rotation slerped.</summary>
        public static UnityPose Lerp(UnityPose a, UnityPose b, double t) =>
            new UnityPose(a.Position + (b.Position - a.Position) * t, Slerp(a.Rotation, b.Rotation, t));

        /// <summary>
        /// instant-ngp's <c>camera_slerp</c> on two output camera-to-world matrices (rotations with det +1): the
        /// rotation slerped, the centre mixed linearly.
        /// </summary>
        public static Matrix4x4d Lerp(Matrix4x4d a, Matrix4x4d b, double t)
        {
            var qa = Quaterniond.FromBasis(a.Column(0), a.Column(1), a.Column(2));
            var qb = Quaterniond.FromBasis(b.Column(0), b.Column(1), b.Column(2));
            var q = Slerp(qa, qb, t);
            return Matrix4x4d.FromColumns(q.Rotate(Vector3d.UnitX), q.Rotate(Vector3d.UnitY), q.Rotate(Vector3d.UnitZ),
                a.Translation + (b.Translation - a.Translation) * t);
        }

        /// <summary>The rotation by |ω| radians about ω (the exponential map); identity for ω = 0.</summary>
        public static Quaterniond FromRotationVector(Vector3d omega)
        {
            var angle = omega.Length;
            if (angle < 1e-300) return Quaterniond.Identity;
            var s = Math.Sin(angle / 2) / angle;
            return new Quaterniond(omega.X * s, omega.Y * s, omega.Z * s, Math.Cos(angle / 2));
        }

        /// <summary>The rotation vector (axis × angle in radians, angle in [0, π]) of a unit quaternion: the inverse of <see cref="FromRotationVector"/>.</summary>
        public static Vector3d ToRotationVector(Quaterniond q)
        {
            if (q.W < 0) q = new Quaterniond(-q.X, -q.Y, -q.Z, -q.W);
            var v = Math.Sqrt(q.X * q.X + q.Y * q.Y + q.Z * q.Z);
            if (v < 1e-300) return Vector3d.Zero;
            var angle = 2 * Math.Atan2(v, q.W);
            return new Vector3d(q.X, q.Y, q.Z) * (angle / v);
        }

        /// <summary>The inverse of a unit quaternion.</summary>
        public static Quaterniond Inverse(Quaterniond q) => new Quaterniond(-q.X, -q.Y, -q.Z, q.W);
    }
}
