namespace NerfDatasetCreator
{
    /// <summary>Frames for the normal pass. The shader writes Unity world normals; datasets use the output world frame.</summary>
    public static class NormalFrames
    {
        /// <summary>
        /// Relabels RGBA float normals (x, y, z, coverage) in place from Unity's world frame to the output world frame
        /// with <see cref="BlenderConvention.FromUnity"/>. Pixels without geometry stay (0, 0, 0, 0). Thread-safe.
        /// </summary>
        public static void ToOutputWorld(float[] rgba)
        {
            for (var i = 0; i + 3 < rgba.Length; i += 4)
            {
                var n = BlenderConvention.FromUnity(new Vector3d(rgba[i], rgba[i + 1], rgba[i + 2]));
                rgba[i] = (float)n.X;
                rgba[i + 1] = (float)n.Y;
                rgba[i + 2] = (float)n.Z;
            }
        }
    }
}
