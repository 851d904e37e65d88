using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A box in Unity's world: a centre, a rotation and its full size along its own axes — a Transform's unit cube
    /// (position, rotation, lossy scale), a BoxCollider (its centre and size through its Transform), or an
    /// axis-aligned <c>Bounds</c> (identity rotation).
    /// </summary>
    [Serializable]
    public sealed class OrientedBox
    {
        public OrientedBox(string name, Vector3d centre, Quaterniond rotation, Vector3d size)
        {
            Name = name ?? "";
            Centre = centre;
            Rotation = rotation.Normalized();
            Size = size;
        }

        /// <summary>An axis-aligned box, e.g. a Unity <c>Bounds</c>.</summary>
        public static OrientedBox AxisAligned(string name, Vector3d centre, Vector3d size) => new OrientedBox(name, centre, Quaterniond.Identity, size);

        /// <summary>The object it came from (hierarchy path), for messages.</summary>
        public string Name { get; }

        public Vector3d Centre { get; }
        public Quaterniond Rotation { get; }

        /// <summary>Full extent along the box's own x, y, z (absolute values are used).</summary>
        public Vector3d Size { get; }

        public double Volume => Math.Abs(Size.X * Size.Y * Size.Z);

        public bool IsFinite => Centre.IsFinite && Size.IsFinite && new Vector3d(Rotation.X, Rotation.Y, Rotation.Z).IsFinite && !double.IsNaN(Rotation.W) && !double.IsInfinity(Rotation.W);

        /// <summary>The world point at box coordinates <paramref name="local"/>, each in [−½, ½] inside the box.</summary>
        public Vector3d PointAt(Vector3d local) =>
            Centre + Rotation.Rotate(new Vector3d(local.X * Size.X, local.Y * Size.Y, local.Z * Size.Z));

        /// <summary>
        /// Whether <paramref name="point"/> is inside the box grown by <paramref name="margin"/> on every side (a
        /// box-shaped margin: at a corner it reaches a little further than a distance would).
        /// </summary>
        public bool Contains(Vector3d point, double margin = 0)
        {
            var inverse = new Quaterniond(-Rotation.X, -Rotation.Y, -Rotation.Z, Rotation.W);
            var p = inverse.Rotate(point - Centre);
            return Math.Abs(p.X) <= Math.Abs(Size.X) / 2 + margin
                && Math.Abs(p.Y) <= Math.Abs(Size.Y) / 2 + margin
                && Math.Abs(p.Z) <= Math.Abs(Size.Z) / 2 + margin;
        }
    }
}
