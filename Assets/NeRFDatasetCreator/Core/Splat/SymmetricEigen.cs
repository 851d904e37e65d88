using System;

namespace NerfDatasetCreator
{
    /// <summary>Eigenvalues and unit eigenvectors of a symmetric 3×3 matrix by cyclic Jacobi rotations (numpy's eigh up to each vector's sign).</summary>
    public static class SymmetricEigen
    {
        public static (double[] Values, Vector3d[] Vectors) Solve(double[,] matrix)
        {
            var a = (double[,])matrix.Clone();
            var v = new double[3, 3] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            for (var sweep = 0; sweep < 64; sweep++)
            {
                var off = Math.Abs(a[0, 1]) + Math.Abs(a[0, 2]) + Math.Abs(a[1, 2]);
                var scale = Math.Abs(a[0, 0]) + Math.Abs(a[1, 1]) + Math.Abs(a[2, 2]);
                if (off <= 1e-300 || off <= 1e-17 * scale) break;
                for (var p = 0; p < 2; p++)
                for (var q = p + 1; q < 3; q++)
                {
                    if (a[p, q] == 0) continue;
                    var theta = (a[q, q] - a[p, p]) / (2 * a[p, q]);
                    var t = Math.Sign(theta == 0 ? 1 : theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                    var c = 1 / Math.Sqrt(t * t + 1);
                    var s = t * c;
                    for (var k = 0; k < 3; k++)
                    {
                        double akp = a[k, p], akq = a[k, q];
                        a[k, p] = c * akp - s * akq;
                        a[k, q] = s * akp + c * akq;
                    }
                    for (var k = 0; k < 3; k++)
                    {
                        double apk = a[p, k], aqk = a[q, k];
                        a[p, k] = c * apk - s * aqk;
                        a[q, k] = s * apk + c * aqk;
                    }
                    for (var k = 0; k < 3; k++)
                    {
                        double vkp = v[k, p], vkq = v[k, q];
                        v[k, p] = c * vkp - s * vkq;
                        v[k, q] = s * vkp + c * vkq;
                    }
                }
            }
            var values = new[] { a[0, 0], a[1, 1], a[2, 2] };
            var vectors = new Vector3d[3];
            for (var i = 0; i < 3; i++) vectors[i] = new Vector3d(v[0, i], v[1, i], v[2, i]).Normalized();
            return (values, vectors);
        }
    }
}
