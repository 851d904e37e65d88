using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>How the cameras of a capture meet time (Documentation~/dynamic-capture.md).</summary>
    public enum TimeMode
    {
        /// <summary>No time: the content is captured as it stands (every static dataset).</summary>
        Static = 0,

        /// <summary>
        /// D-NeRF style: one view per time step, each split's views spread over the time range in order; val and test
        /// views sit between the train times (view 0 of every split at time 0, which D-NeRF's loader asserts).
        /// </summary>
        Monocular = 1,

        /// <summary>Every camera of every split's formation at every time step.</summary>
        MultiView = 2,
    }

    /// <summary>The config-file names of <see cref="TimeMode"/>.</summary>
    public static class TimeModes
    {
        public static readonly IReadOnlyList<TimeMode> All = new[] { TimeMode.Static, TimeMode.Monocular, TimeMode.MultiView };

        public static string Name(TimeMode mode)
        {
            switch (mode)
            {
                case TimeMode.Static: return "static";
                case TimeMode.Monocular: return "monocular";
                case TimeMode.MultiView: return "multi-view";
                default: throw new ArgumentOutOfRangeException(nameof(mode), mode, "not a time mode");
            }
        }

        public static bool IsDefined(TimeMode mode) => mode == TimeMode.Static || mode == TimeMode.Monocular || mode == TimeMode.MultiView;

        public static bool TryParse(string name, out TimeMode mode)
        {
            foreach (var m in All)
                if (string.Equals(Name(m), name, StringComparison.OrdinalIgnoreCase))
                {
                    mode = m;
                    return true;
                }
            mode = TimeMode.Static;
            return false;
        }

        public static string NameList() => string.Join(", ", new List<TimeMode>(All).ConvertAll(m => "\"" + Name(m) + "\""));
    }
}
