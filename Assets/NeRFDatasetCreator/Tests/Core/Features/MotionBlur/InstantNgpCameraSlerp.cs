using System;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// instant-ngp's pose between a frame's start and end matrices, written independently of Core's quaternions:
    /// <c>camera_slerp(a, b, t)</c> (NVlabs/instant-ngp include/neural-graphics-primitives/common_device.cuh) mixes the
    /// positions linearly and slerps the rotations, R(t) = exp(t·log(R_b·R_aᵀ))·R_a, here with Rodrigues' formula on
    /// 3×3 matrices; the pixel's t is A + B·u + C·v + D·r from <c>rolling_shutter</c> (<c>get_xform_given_rolling_shutter</c>).
    /// </summary>
    static class InstantNgpCameraSlerp
    {
        public static double PixelTime(double[] rollingShutter, double u, double v, double r) =>
            rollingShutter[0] + rollingShutter[1] * u + rollingShutter[2] * v + rollingShutter[3] * r;

        public static double[,] At(double[,] a, double[,] b, double t)
        {
            var ra = Rotation(a);
            var rb = Rotation(b);
            var relative = Multiply(rb, Transpose(ra));
            var rotation = Multiply(Exp(Scale(Log(relative), t)), ra);
            var result = new double[4, 4];
            for (var r = 0; r < 3; r++)
            {
                for (var c = 0; c < 3; c++) result[r, c] = rotation[r, c];
                result[r, 3] = a[r, 3] + (b[r, 3] - a[r, 3]) * t;
            }
            result[3, 3] = 1;
            return result;
        }

        static double[,] Rotation(double[,] m)
        {
            var r = new double[3, 3];
            for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++) r[i, j] = m[i, j];
            return r;
        }

        static double[,] Transpose(double[,] m)
        {
            var t = new double[3, 3];
            for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++) t[i, j] = m[j, i];
            return t;
        }

        static double[,] Multiply(double[,] a, double[,] b)
        {
            var m = new double[3, 3];
            for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++)
                    for (var k = 0; k < 3; k++) m[i, j] += a[i, k] * b[k, j];
            return m;
        }

        // log of a rotation as the rotation vector (angle < π).
        static double[] Log(double[,] r)
        {
            var cos = Math.Max(-1, Math.Min(1, (r[0, 0] + r[1, 1] + r[2, 2] - 1) / 2));
            var angle = Math.Acos(cos);
            var w = new[] { r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1] };
            if (angle < 1e-12) return new[] { w[0] / 2, w[1] / 2, w[2] / 2 };
            var f = angle / (2 * Math.Sin(angle));
            return new[] { w[0] * f, w[1] * f, w[2] * f };
        }

        static double[] Scale(double[] v, double s) => new[] { v[0] * s, v[1] * s, v[2] * s };

        // Rodrigues: exp([ω]×) = I + sin θ K + (1 − cos θ) K², K the unit axis' cross-product matrix.
        static double[,] Exp(double[] w)
        {
            var angle = Math.Sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            var m = new double[3, 3] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            if (angle < 1e-300) return m;
            double x = w[0] / angle, y = w[1] / angle, z = w[2] / angle;
            var k = new double[3, 3] { { 0, -z, y }, { z, 0, -x }, { -y, x, 0 } };
            var k2 = Multiply(k, k);
            for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++) m[i, j] += Math.Sin(angle) * k[i, j] + (1 - Math.Cos(angle)) * k2[i, j];
            return m;
        }

        public static double[,] FromJson(Newtonsoft.Json.Linq.JToken token)
        {
            var m = new double[4, 4];
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++) m[r, c] = (double)token[r][c];
            return m;
        }

        public static double MaxDifference(double[,] a, Matrix4x4d b)
        {
            var max = 0.0;
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++) max = Math.Max(max, Math.Abs(a[r, c] - b[r, c]));
            return max;
        }
    }
}
