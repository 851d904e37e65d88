namespace NerfDatasetCreator
{
    /// <summary>What a run may do when the dataset folder already exists. Nothing is ever appended to.</summary>
    public enum OverwritePolicy
    {
        /// <summary>Refuse to run (the default): an existing dataset is never touched.</summary>
        Never,
        /// <summary>Replace the whole existing dataset, but only once the new one is complete.</summary>
        Replace,
    }
}
