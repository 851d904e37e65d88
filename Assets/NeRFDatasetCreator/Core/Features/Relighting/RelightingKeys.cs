namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame key of the relighting sets (issue 38): <c>relit_paths</c>, an object from each condition's file key
    /// (<c>sunset_090</c>, <c>olat-03</c>) to that view's PNG under it (<c>./train/r_0_light_sunset_090.png</c>), and the
    /// lights file every dataset with relighting holds.
    /// </summary>
    public static class RelightingKeys
    {
        public const string RelitPaths = "relit_paths";

        /// <summary>The lights record, relative to the dataset root.</summary>
        public const string LightsFile = "lights/lights.json";
    }
}
