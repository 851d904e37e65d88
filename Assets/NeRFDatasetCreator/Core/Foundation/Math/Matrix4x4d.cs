using System;
using System.Globalization;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A double-precision 4×4 matrix indexed [row, column], like Unity's <c>Matrix4x4</c> and like the row-major
    /// nested lists of a transforms file (<c>transform_matrix[row][column]</c>).
    /// </summary>
    [Serializable]
    public readonly struct Matrix4x4d : IEquatable<Matrix4x4d>
    {
        readonly double[] _m; // row-major, 16 entries

        Matrix4x4d(double[] rowMajor) => _m = rowMajor;

        /// <summary>A matrix from 16 entries in row-major order (copied).</summary>
        public static Matrix4x4d FromRowMajor(params double[] rowMajor)
        {
            if (rowMajor == null || rowMajor.Length != 16)
                throw new ArgumentException("A 4×4 matrix needs exactly 16 entries.", nameof(rowMajor));
            return new Matrix4x4d((double[])rowMajor.Clone());
        }

        /// <summary>A rigid transform with the given columns (x, y, z axes and translation) and last row 0 0 0 1.</summary>
        public static Matrix4x4d FromColumns(Vector3d c0, Vector3d c1, Vector3d c2, Vector3d c3) => new Matrix4x4d(new[]
        {
            c0.X, c1.X, c2.X, c3.X,
            c0.Y, c1.Y, c2.Y, c3.Y,
            c0.Z, c1.Z, c2.Z, c3.Z,
            0, 0, 0, 1.0,
        });

        public static Matrix4x4d Identity => FromColumns(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ, Vector3d.Zero);

        public double this[int row, int column] => _m[row * 4 + column];

        public Vector3d Column(int column) => new Vector3d(this[0, column], this[1, column], this[2, column]);

        public Vector3d Translation => Column(3);

        /// <summary>The rows as nested arrays, the shape a transforms file stores.</summary>
        public double[][] ToRows()
        {
            var rows = new double[4][];
            for (var r = 0; r < 4; r++)
            {
                rows[r] = new double[4];
                Array.Copy(_m, r * 4, rows[r], 0, 4);
            }
            return rows;
        }

        /// <summary>The matrix from nested rows, as read from a transforms file.</summary>
        public static Matrix4x4d FromRows(double[][] rows)
        {
            if (rows == null || rows.Length != 4)
                throw new ArgumentException("A 4×4 matrix needs 4 rows.", nameof(rows));
            var m = new double[16];
            for (var r = 0; r < 4; r++)
            {
                if (rows[r] == null || rows[r].Length != 4)
                    throw new ArgumentException("Row " + r + " of a 4×4 matrix needs 4 entries.", nameof(rows));
                Array.Copy(rows[r], 0, m, r * 4, 4);
            }
            return new Matrix4x4d(m);
        }

        /// <summary>Applies the affine part to a point (w = 1).</summary>
        public Vector3d MultiplyPoint(Vector3d p) => new Vector3d(
            this[0, 0] * p.X + this[0, 1] * p.Y + this[0, 2] * p.Z + this[0, 3],
            this[1, 0] * p.X + this[1, 1] * p.Y + this[1, 2] * p.Z + this[1, 3],
            this[2, 0] * p.X + this[2, 1] * p.Y + this[2, 2] * p.Z + this[2, 3]);

        /// <summary>Applies the linear 3×3 part to a direction (w = 0).</summary>
        public Vector3d MultiplyVector(Vector3d v) => new Vector3d(
            this[0, 0] * v.X + this[0, 1] * v.Y + this[0, 2] * v.Z,
            this[1, 0] * v.X + this[1, 1] * v.Y + this[1, 2] * v.Z,
            this[2, 0] * v.X + this[2, 1] * v.Y + this[2, 2] * v.Z);

        public static Matrix4x4d operator *(Matrix4x4d a, Matrix4x4d b)
        {
            var m = new double[16];
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                {
                    double sum = 0;
                    for (var k = 0; k < 4; k++) sum += a[r, k] * b[k, c];
                    m[r * 4 + c] = sum;
                }
            return new Matrix4x4d(m);
        }

        /// <summary>Determinant of the upper-left 3×3 block: +1 for a proper rotation, −1 for a mirrored frame.</summary>
        public double Determinant3x3 =>
            this[0, 0] * (this[1, 1] * this[2, 2] - this[1, 2] * this[2, 1]) -
            this[0, 1] * (this[1, 0] * this[2, 2] - this[1, 2] * this[2, 0]) +
            this[0, 2] * (this[1, 0] * this[2, 1] - this[1, 1] * this[2, 0]);

        /// <summary>The inverse of a rigid transform (rotation + translation): [Rᵀ | −Rᵀt].</summary>
        public Matrix4x4d InverseRigid()
        {
            var r0 = new Vector3d(this[0, 0], this[1, 0], this[2, 0]);
            var r1 = new Vector3d(this[0, 1], this[1, 1], this[2, 1]);
            var r2 = new Vector3d(this[0, 2], this[1, 2], this[2, 2]);
            var t = Translation;
            return new Matrix4x4d(new[]
            {
                r0.X, r0.Y, r0.Z, -Vector3d.Dot(r0, t),
                r1.X, r1.Y, r1.Z, -Vector3d.Dot(r1, t),
                r2.X, r2.Y, r2.Z, -Vector3d.Dot(r2, t),
                0, 0, 0, 1.0,
            });
        }

        public bool IsFinite
        {
            get
            {
                foreach (var v in _m)
                    if (double.IsNaN(v) || double.IsInfinity(v)) return false;
                return true;
            }
        }

        public bool Equals(Matrix4x4d other)
        {
            for (var i = 0; i < 16; i++)
                if (!_m[i].Equals(other._m[i])) return false;
            return true;
        }

        public override bool Equals(object obj) => obj is Matrix4x4d other && Equals(other);

        public override int GetHashCode()
        {
            var hash = new HashCode();
            foreach (var v in _m) hash.Add(v);
            return hash.ToHashCode();
        }

        public override string ToString()
        {
            var sb = new StringBuilder();
            for (var r = 0; r < 4; r++)
                sb.AppendFormat(CultureInfo.InvariantCulture, "[{0:R}, {1:R}, {2:R}, {3:R}]{4}", this[r, 0], this[r, 1], this[r, 2], this[r, 3], r < 3 ? "\n" : "");
            return sb.ToString();
        }
    }
}
