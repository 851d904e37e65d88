using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A splat's world placement (<see cref="SplatPlacement.ObjectToWorld"/>) as a child of the target's parent: the
    /// Transform's localPosition, localRotation and localScale (one negative component, z, carries a reflection, as
    /// the issue-34 placement writes it) that give that world matrix under the parent, or why no Transform can.
    /// </summary>
    public sealed class SplatUnderParent
    {
        SplatUnderParent(Vector3d position, Quaterniond rotation, Vector3d scale)
        {
            Position = position;
            Rotation = rotation;
            Scale = scale;
        }

        public Vector3d Position { get; }
        public Quaterniond Rotation { get; }
        public Vector3d Scale { get; }

        /// <summary>
        /// The local transform giving <paramref name="objectToWorld"/> under a parent whose <c>worldToLocalMatrix</c> is
        /// <paramref name="parentWorldToLocal"/> (null: no parent); null with <paramref name="problem"/> when the product is
        /// sheared (a parent scaled unevenly and rotated against the splat), which no Transform can express.
        /// </summary>
        public static SplatUnderParent Local(Matrix4x4d? parentWorldToLocal, Matrix4x4d objectToWorld, out string problem)
        {
            var m = parentWorldToLocal.HasValue ? parentWorldToLocal.Value * objectToWorld : objectToWorld;
            problem = null;
            if (!m.IsFinite) { problem = "the placement matrix is not finite."; return null; }
            Vector3d c0 = m.Column(0), c1 = m.Column(1), c2 = m.Column(2);
            double l0 = c0.Length, l1 = c1.Length, l2 = c2.Length;
            if (!(l0 > 0 && l1 > 0 && l2 > 0)) { problem = "the placement matrix collapses an axis."; return null; }
            const double tolerance = 1e-6;
            if (Math.Abs(Vector3d.Dot(c0, c1)) > tolerance * l0 * l1 || Math.Abs(Vector3d.Dot(c0, c2)) > tolerance * l0 * l2 ||
                Math.Abs(Vector3d.Dot(c1, c2)) > tolerance * l1 * l2)
            {
                problem = "the target's parent is scaled unevenly and rotated against the splat, so the placement would be sheared under it.";
                return null;
            }
            // A reflection (negative determinant) goes into z's scale, so that the rotation is proper.
            var sz = m.Determinant3x3 < 0 ? -l2 : l2;
            var rotation = Quaterniond.FromBasis(c0 / l0, c1 / l1, c2 / sz);
            return new SplatUnderParent(m.Translation, rotation, new Vector3d(l0, l1, sz));
        }
    }
}
