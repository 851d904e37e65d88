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
            : this(centre, boundingRadius, clipLengthSeconds, false)
        {
        }

        PlanTarget(Vector3d centre, double boundingRadius, double clipLengthSeconds, bool headless)
        {
            Centre = centre;
            BoundingRadius = boundingRadius;
            ClipLengthSeconds = clipLengthSeconds;
            IsHeadless = headless;
        }

        public Vector3d Centre { get; }
        public double BoundingRadius { get; }

        /// <summary>The length of the target's longest clip or Timeline in seconds, for <c>time.end: "clip"</c> (0 when unknown).</summary>
        public double ClipLengthSeconds { get; }

        /// <summary>A target at the Unity origin with unknown bounds (the headless tool's case).</summary>
        public static PlanTarget AtOrigin => new PlanTarget(Vector3d.Zero, 0);

        /// <summary>
        /// The headless tool's target: at the origin with unknown bounds, and no scene to pick another from, so a
        /// message asks for a number rather than "a target with renderers".
        /// </summary>
        public static PlanTarget Headless => new PlanTarget(Vector3d.Zero, 0, 0, true);

        /// <summary>
        /// The headless tool's target for <c>time.end: "clip"</c>: the clip's length is known only in Unity, so the plan
        /// assumes <paramref name="assumedClipLengthSeconds"/> and says so (<see cref="HeadlessClip"/>).
        /// </summary>
        public static PlanTarget HeadlessWithClip(double assumedClipLengthSeconds) => new PlanTarget(Vector3d.Zero, 0, assumedClipLengthSeconds, true);

        /// <summary>True for <see cref="Headless"/>: there is no scene, so no target can be picked.</summary>
        public bool IsHeadless { get; }

        public bool HasBounds => BoundingRadius > 0 && !double.IsInfinity(BoundingRadius);
    }
}
