namespace NerfDatasetCreator
{
    /// <summary>How <see cref="DatasetFolder"/> treats what is odd in a transforms file.</summary>
    public enum DatasetReadMode
    {
        /// <summary>
        /// Every problem is collected (validate, check, evaluate): a required key that is missing, a value of the wrong
        /// type, and — in <see cref="DatasetFrame.FileProblems"/> — every file a key names that leaves the dataset or is missing.
        /// </summary>
        Strict,

        /// <summary>
        /// What can be read is read and the rest is null, without problems (convert of nerf_synthetic and other tools'
        /// datasets, imported poses of any transforms file): the caller words what it cannot use. Files outside the
        /// dataset are still never resolved.
        /// </summary>
        Lenient,
    }
}
