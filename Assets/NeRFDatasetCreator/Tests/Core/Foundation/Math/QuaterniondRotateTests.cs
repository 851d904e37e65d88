using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <see cref="Quaterniond.Rotate"/> is written out in scalars for Mono's sake; it must give the very bits of the
    /// vector formula it replaced (every plan's transform_matrix comes from it, and the golden files pin them).
    /// </summary>
    public class QuaterniondRotateTests
    {
        [Test]
        public void GivesTheBitsOfTheVectorFormula()
        {
            var random = new SeededRandom(77);
            var axes = new[] { Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ };
            for (var i = 0; i < 20000; i++)
            {
                var q = new Quaterniond(Draw(random), Draw(random), Draw(random), Draw(random)).Normalized();
                var v = i % 4 < 3 ? axes[i % 4] : new Vector3d(Draw(random) * 10, Draw(random), Draw(random) * 1e-3);
                var expected = VectorFormula(q, v);
                var actual = q.Rotate(v);
                Assert.That(Bits(actual.X), Is.EqualTo(Bits(expected.X)), "x of " + q + " · " + v);
                Assert.That(Bits(actual.Y), Is.EqualTo(Bits(expected.Y)), "y of " + q + " · " + v);
                Assert.That(Bits(actual.Z), Is.EqualTo(Bits(expected.Z)), "z of " + q + " · " + v);
            }
            // A 90° turn about +Y takes +Z to +X: the formula itself, not only its equal.
            var quarter = new Quaterniond(0, Math.Sqrt(0.5), 0, Math.Sqrt(0.5));
            var turned = quarter.Rotate(Vector3d.UnitZ);
            Assert.That(turned.X, Is.EqualTo(1).Within(1e-15));
            Assert.That(turned.Y, Is.EqualTo(0).Within(1e-15));
            Assert.That(turned.Z, Is.EqualTo(0).Within(1e-15));
        }

        // The implementation before it was written out: v + w·t + q×t, t = 2(q×v).
        static Vector3d VectorFormula(Quaterniond q, Vector3d v)
        {
            var axis = new Vector3d(q.X, q.Y, q.Z);
            var t = 2.0 * Vector3d.Cross(axis, v);
            return v + q.W * t + Vector3d.Cross(axis, t);
        }

        static double Draw(SeededRandom random) => random.NextDouble() * 2 - 1;

        static long Bits(double value) => BitConverter.DoubleToInt64Bits(value);
    }
}
