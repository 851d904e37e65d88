using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Camera centre and viewing direction of a NeRF/OpenGL c2w (translation, −third column) and comparisons.</summary>
    static class PoseAssert
    {
        public static double[] Centre(double[][] c2w) => new[] { c2w[0][3], c2w[1][3], c2w[2][3] };

        public static double[] ViewDirection(double[][] c2w) => new[] { -c2w[0][2], -c2w[1][2], -c2w[2][2] };

        /// <summary>Asserts closeness and returns the largest component difference (printed as a figure).</summary>
        public static double Close(double[] actual, double[] expected, double tolerance, string what)
        {
            Assert.That(actual.Length, Is.EqualTo(3), what);
            double worst = 0;
            for (var i = 0; i < 3; i++)
            {
                Assert.That(actual[i], Is.EqualTo(expected[i]).Within(tolerance), what + "[" + i + "]");
                worst = Math.Max(worst, Math.Abs(actual[i] - expected[i]));
            }
            return worst;
        }

        public static double[] Normalised(double[] v)
        {
            var n = Math.Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            return new[] { v[0] / n, v[1] / n, v[2] / n };
        }
    }
}
