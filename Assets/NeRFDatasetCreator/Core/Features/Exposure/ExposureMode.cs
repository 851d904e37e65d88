using System;

namespace NerfDatasetCreator
{
    /// <summary>Where the per-view exposure and white balance come from (<see cref="ExposureSettings"/>).</summary>
    public enum ExposureMode
    {
        /// <summary>No exposure stage: images, transforms files and configs exactly as without the feature.</summary>
        Off,
        /// <summary>Drawn per view from a seeded distribution (<see cref="ExposurePlan"/>).</summary>
        Random,
        /// <summary>Taken from an explicit list, entry i mod n for view i.</summary>
        List,
    }

    /// <summary>The config-file names of <see cref="ExposureMode"/>.</summary>
    public static class ExposureModes
    {
        public static readonly ExposureMode[] All = { ExposureMode.Off, ExposureMode.Random, ExposureMode.List };

        public static string Name(ExposureMode mode)
        {
            switch (mode)
            {
                case ExposureMode.Off: return "off";
                case ExposureMode.Random: return "random";
                case ExposureMode.List: return "list";
                default: throw new ArgumentOutOfRangeException(nameof(mode), mode, "not an exposure mode");
            }
        }

        public static bool IsDefined(ExposureMode mode) => mode >= ExposureMode.Off && mode <= ExposureMode.List;

        public static bool TryParse(string name, out ExposureMode mode)
        {
            foreach (var m in All)
                if (string.Equals(Name(m), name, StringComparison.OrdinalIgnoreCase))
                {
                    mode = m;
                    return true;
                }
            mode = ExposureMode.Off;
            return false;
        }

        public static string NameList() => "\"off\", \"random\", \"list\"";
    }
}
