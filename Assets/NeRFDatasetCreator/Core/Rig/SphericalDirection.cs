using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A direction from the target to a camera, as azimuth and elevation in Unity's world (+Y up):
    /// (cos e·cos a, sin e, cos e·sin a). In the Blender output world (x, z, y) this is the usual spherical
    /// direction, azimuth counter-clockwise from +X seen from above. Keeping the azimuth even at the poles is what
    /// gives a camera straight above or below the target a defined roll (see <see cref="LookAt"/>).
    /// </summary>
    [Serializable]
    public readonly struct SphericalDirection
    {
        public SphericalDirection(double azimuthRadians, double elevationRadians)
        {
            AzimuthRadians = azimuthRadians;
            ElevationRadians = elevationRadians;
        }

        public double AzimuthRadians { get; }
        public double ElevationRadians { get; }

        public static SphericalDirection FromDegrees(double azimuthDegrees, double elevationDegrees) =>
            new SphericalDirection(azimuthDegrees * Math.PI / 180.0, elevationDegrees * Math.PI / 180.0);

        /// <summary>The unit vector in Unity's world.</summary>
        public Vector3d ToUnityVector()
        {
            var cosE = Math.Cos(ElevationRadians);
            return new Vector3d(cosE * Math.Cos(AzimuthRadians), Math.Sin(ElevationRadians), cosE * Math.Sin(AzimuthRadians));
        }

        /// <summary>
        /// The direction of a (non-zero) Unity vector. Straight up or down the azimuth is 0, so a camera placed on
        /// the pole by position alone rolls like its neighbours at azimuth 0.
        /// </summary>
        public static SphericalDirection FromUnityVector(Vector3d v)
        {
            var horizontal = Math.Sqrt(v.X * v.X + v.Z * v.Z);
            var azimuth = horizontal > 0 ? Math.Atan2(v.Z, v.X) : 0.0; // Atan2(±0, -0) would be ±π
            return new SphericalDirection(azimuth, Math.Atan2(v.Y, horizontal));
        }
    }
}
