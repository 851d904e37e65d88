namespace NerfDatasetCreator
{
    /// <summary>
    /// What the Unity side knows about the target when planning: its centre in the Unity world (the cameras aim
    /// at it, and output poses are recentred on it) and the radius of a sphere about that centre holding all its
    /// renderers (0 when unknown — then an automatic distance is impossible and the clip checks are skipped).
    /// </summary>
    public readonly struct PlanTarget
    {
        public PlanTarget(Vector3d centre, double boundingRadius, double clipLengthSeconds = 0)
        {
            Centre = centre;
            BoundingRadius = boundingRadius;
            ClipLengthSeconds = clipLengthSeconds;
        }

        public Vector3d Centre { get; }
        public double BoundingRadius { get; }

        /// <summary>The length of the target's longest clip or Timeline in seconds, for <c>time.end: "clip"</c> (0 when unknown).</summary>
        public double ClipLengthSeconds { get; }

        /// <summary>A target at the Unity origin with unknown bounds (the headless tool's case).</summary>
        public static PlanTarget AtOrigin => new PlanTarget(Vector3d.Zero, 0);

        public bool HasBounds => BoundingRadius > 0 && !double.IsInfinity(BoundingRadius);
    }
}
