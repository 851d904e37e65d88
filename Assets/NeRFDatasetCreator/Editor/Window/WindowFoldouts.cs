using System;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Which parts of the window are open; window state (kept across domain reloads), not dataset settings.</summary>
    [Serializable]
    sealed class WindowFoldouts
    {
        public bool TrainAdvanced;
        public bool ValAdvanced;
        public bool TestAdvanced;
        public bool PresetsAndConfig = true;

        /// <summary>The user chose "Custom" resolution: keep showing width and height even for a preset size.</summary>
        public bool CustomResolution;

        public bool Advanced(DatasetSplit split) =>
            split == DatasetSplit.Train ? TrainAdvanced : split == DatasetSplit.Val ? ValAdvanced : TestAdvanced;

        public void SetAdvanced(DatasetSplit split, bool open)
        {
            if (split == DatasetSplit.Train) TrainAdvanced = open;
            else if (split == DatasetSplit.Val) ValAdvanced = open;
            else TestAdvanced = open;
        }
    }
}
