using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The "hdr" section of the settings: beside each colour image of the chosen splits, its linear colour as a float
    /// EXR, <c>r_&lt;i&gt;_hdr.exr</c> (RGB with straight alpha, before the clip to [0, 1], before exposure and white
    /// balance; Documentation~/settings.md, maintainers/layouts-multiscale-hdr.md). Off by default, and then nothing
    /// about the dataset changes.
    /// </summary>
    [Serializable]
    public sealed class HdrSettings
    {
        /// <summary>On when the section is given (and not <c>"enabled": false</c>).</summary>
        public bool On;

        /// <summary>The splits whose views get the EXR (all three by default).</summary>
        public bool Train = true, Val = true, Test = true;

        public bool Enabled => On;

        /// <summary>True when the views of <paramref name="split"/> get the EXR.</summary>
        public bool Applies(DatasetSplit split) =>
            Enabled && (split == DatasetSplit.Train ? Train : split == DatasetSplit.Val ? Val : Test);

        public HdrSettings Clone() => (HdrSettings)MemberwiseClone();
    }
}
