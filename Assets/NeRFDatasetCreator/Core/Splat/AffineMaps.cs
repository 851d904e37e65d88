using System;

namespace NerfDatasetCreator
{
    /// <summary>The few affine-matrix operations placement needs (Matrix4x4d has only the rigid inverse).</summary>
    public static class AffineMaps
    {
        /// <summary>The inverse of an affine 4×4 (last row 0 0 0 1) with an invertible 3×3 block.</summary>
        public static Matrix4x4d Inverse(Matrix4x4d m)
        {
            double a = m[0, 0], b = m[0, 1], c = m[0, 2], d = m[1, 0], e = m[1, 1], f = m[1, 2], g = m[2, 0], h = m[2, 1], k = m[2, 2];
            var det = m.Determinant3x3;
            if (det == 0 || double.IsNaN(det)) throw new ArgumentException("The matrix is not invertible (its 3×3 block has determinant " + det + ").", nameof(m));
            var i00 = (e * k - f * h) / det; var i01 = (c * h - b * k) / det; var i02 = (b * f - c * e) / det;
            var i10 = (f * g - d * k) / det; var i11 = (a * k - c * g) / det; var i12 = (c * d - a * f) / det;
            var i20 = (d * h - e * g) / det; var i21 = (b * g - a * h) / det; var i22 = (a * e - b * d) / det;
            var t = m.Translation;
            return Matrix4x4d.FromRowMajor(
                i00, i01, i02, -(i00 * t.X + i01 * t.Y + i02 * t.Z),
                i10, i11, i12, -(i10 * t.X + i11 * t.Y + i12 * t.Z),
                i20, i21, i22, -(i20 * t.X + i21 * t.Y + i22 * t.Z),
                0, 0, 0, 1);
        }

        /// <summary>16 numbers, row-major.</summary>
        public static double[] RowMajor(Matrix4x4d m)
        {
            var values = new double[16];
            for (var i = 0; i < 16; i++) values[i] = m[i / 4, i % 4];
            return values;
        }

        /// <summary>A 3×4 block (nerfstudio's dataparser transform) as a 4×4 with the row 0 0 0 1.</summary>
        public static Matrix4x4d FromRows3x4(double[][] rows) => Matrix4x4d.FromRowMajor(
            rows[0][0], rows[0][1], rows[0][2], rows[0][3],
            rows[1][0], rows[1][1], rows[1][2], rows[1][3],
            rows[2][0], rows[2][1], rows[2][2], rows[2][3],
            0, 0, 0, 1);

        /// <summary>x·s for the whole 4×4 except its last row: the uniform scale after an affine map.</summary>
        public static Matrix4x4d Scaled(Matrix4x4d m, double s) => Matrix4x4d.FromRowMajor(
            s * m[0, 0], s * m[0, 1], s * m[0, 2], s * m[0, 3],
            s * m[1, 0], s * m[1, 1], s * m[1, 2], s * m[1, 3],
            s * m[2, 0], s * m[2, 1], s * m[2, 2], s * m[2, 3],
            0, 0, 0, 1);
    }
}
