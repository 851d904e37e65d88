using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The "exposure" section of the settings: per-view exposure (EV) and white-balance gains applied to the colour
    /// images of the chosen splits, in linear light before encoding (Documentation~/exposure.md). Off by default, and
    /// then nothing about the dataset changes.
    /// <para>
    /// White balance is three linear gains (R, G, B), not a temperature and tint: gains are what a camera's white balance
    /// finally applies to its raw channels (a DNG's AsShotNeutral is their inverse), what instant-ngp's learned per-image
    /// exposure is (one log2 multiplier per channel) and what the gsplat/nerfstudio colour corrections can represent,
    /// and they are exact here; a temperature/tint pair needs a colour-science model (Planckian locus, adaptation matrix)
    /// that no trainer shares. The random draw keeps green at 1 (as raw converters normalise gains to green), so the
    /// exposure lives in the EV alone.
    /// </para>
    /// </summary>
    [Serializable]
    public sealed class ExposureSettings
    {
        /// <summary>EV bounds: ±10 stops is a factor of 1024 either way, beyond any useful test.</summary>
        public const double MaxEv = 10;
        /// <summary>Gain bounds, 1/16 … 16 (±4 stops per channel).</summary>
        public const double MinGain = 1.0 / 16, MaxGain = 16;
        /// <summary>The most entries an explicit list may hold.</summary>
        public const int MaxValues = 100000;

        public ExposureMode Mode = ExposureMode.Off;

        /// <summary>The splits whose views are modified; the others keep the plain render and carry no exposure keys.</summary>
        public bool Train = true, Val, Test;

        /// <summary>Random mode: EV uniform in [<see cref="EvMin"/>, <see cref="EvMax"/>].</summary>
        public double EvMin = -1, EvMax = 1;

        /// <summary>Random mode: the R and B gains each log-uniform in [<see cref="GainMin"/>, <see cref="GainMax"/>]; G is 1.</summary>
        public double GainMin = 0.8, GainMax = 1.25;

        /// <summary>List mode: view i of a modified split gets entry i mod the list's length.</summary>
        public List<ViewExposure> Values = new List<ViewExposure>();

        /// <summary>Also write the unmodified image of each modified view, <c>r_&lt;i&gt;_clean.png</c> (key <c>clean_path</c>).</summary>
        public bool WriteClean = true;

        public bool Enabled => Mode != ExposureMode.Off;

        /// <summary>True when the views of <paramref name="split"/> are modified.</summary>
        public bool Applies(DatasetSplit split) =>
            Enabled && (split == DatasetSplit.Train ? Train : split == DatasetSplit.Val ? Val : Test);

        public ExposureSettings Clone()
        {
            var copy = (ExposureSettings)MemberwiseClone();
            copy.Values = Values == null ? new List<ViewExposure>() : new List<ViewExposure>(Values);
            return copy;
        }
    }
}
