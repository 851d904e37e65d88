using System;

namespace NerfDatasetCreator
{
    /// <summary>One split's views: how many, on which formation, and which extra passes each view writes.</summary>
    [Serializable]
    public sealed class SplitSettings
    {
        public int Count = 100;
        public FormationSettings Formation = new FormationSettings();
        public ExtraOutput Depth = ExtraOutput.None;
        public ExtraOutput Normal = ExtraOutput.None;
        public bool Mask;

        /// <summary>Where the split's cameras come from: its formation, or an imported file (see <see cref="CameraSourceSettings"/>).</summary>
        public CameraSourceSettings Source = new CameraSourceSettings();

        public SplitSettings Clone()
        {
            var copy = (SplitSettings)MemberwiseClone();
            copy.Formation = Formation?.Clone();
            copy.Source = Source?.Clone();
            return copy;
        }
    }
}
