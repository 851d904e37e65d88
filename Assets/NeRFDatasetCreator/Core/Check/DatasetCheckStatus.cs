namespace NerfDatasetCreator
{
    /// <summary>The outcome of one check over the whole dataset.</summary>
    public enum DatasetCheckStatus
    {
        Passed,
        Failed,
        /// <summary>Its inputs are missing (e.g. nerf_synthetic has no metric depth); <see cref="DatasetCheckResult.Reason"/> says which.</summary>
        Skipped,
    }
}
