namespace NerfDatasetCreator
{
    /// <summary>What <see cref="DatasetCheck.Run"/> looks at.</summary>
    public sealed class DatasetCheckOptions
    {
        /// <summary>"train", "val" or "test"; null checks every split.</summary>
        public string Split;

        /// <summary>At most this many views per split, spread evenly over it; 0 checks every view.</summary>
        public int MaxViews;
    }
}
