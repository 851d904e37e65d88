using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The config-file names of <see cref="NormalisationMode"/>.</summary>
    public static class NormalisationModes
    {
        public static readonly IReadOnlyList<NormalisationMode> All = new[]
        {
            NormalisationMode.None, NormalisationMode.Recentre, NormalisationMode.NerfSyntheticScale, NormalisationMode.FitTargetRadius,
        };

        public static string Name(NormalisationMode mode)
        {
            switch (mode)
            {
                case NormalisationMode.None: return "none";
                case NormalisationMode.Recentre: return "recentre";
                case NormalisationMode.NerfSyntheticScale: return "nerf-synthetic";
                case NormalisationMode.FitTargetRadius: return "fit-radius";
                default: throw new ArgumentOutOfRangeException(nameof(mode), mode, "not a normalisation mode");
            }
        }

        public static bool IsDefined(NormalisationMode mode) => Array.IndexOf((NormalisationMode[])All, mode) >= 0;

        public static bool TryParse(string name, out NormalisationMode mode)
        {
            foreach (var m in All)
                if (string.Equals(Name(m), name, StringComparison.OrdinalIgnoreCase))
                {
                    mode = m;
                    return true;
                }
            mode = NormalisationMode.Recentre;
            return false;
        }

        public static string NameList() => string.Join(", ", new List<NormalisationMode>(All).ConvertAll(m => "\"" + Name(m) + "\""));
    }
}
