using System;

namespace NerfDatasetCreator
{
    /// <summary>One file a view writes: its kind and its path relative to the dataset folder (forward slashes).</summary>
    [Serializable]
    public sealed class PlannedFile
    {
        public PlannedFile(DatasetFileKind kind, string relativePath)
        {
            Kind = kind;
            RelativePath = relativePath;
        }

        public DatasetFileKind Kind { get; }
        public string RelativePath { get; }
    }
}
