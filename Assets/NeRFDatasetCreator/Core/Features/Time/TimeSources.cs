using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the capture evaluates at each time, on its copies of the target: PlayableDirectors (Timeline), Animators,
    /// legacy Animation components and particle systems found on the target or its children.
    /// </summary>
    [Flags]
    public enum TimeSources
    {
        None = 0,
        Timeline = 1,
        Animator = 2,
        Animation = 4,
        Particles = 8,
        All = Timeline | Animator | Animation | Particles,
    }

    /// <summary>The config-file names of <see cref="TimeSources"/>: a list such as <c>["timeline", "particles"]</c>.</summary>
    public static class TimeSourceNames
    {
        static readonly TimeSources[] Each = { TimeSources.Timeline, TimeSources.Animator, TimeSources.Animation, TimeSources.Particles };

        public static string Name(TimeSources source)
        {
            switch (source)
            {
                case TimeSources.Timeline: return "timeline";
                case TimeSources.Animator: return "animator";
                case TimeSources.Animation: return "animation";
                case TimeSources.Particles: return "particles";
                default: throw new ArgumentOutOfRangeException(nameof(source), source, "not a single time source");
            }
        }

        /// <summary>The names of the sources in <paramref name="sources"/>, in a fixed order.</summary>
        public static IReadOnlyList<string> NamesOf(TimeSources sources)
        {
            var names = new List<string>();
            foreach (var s in Each)
                if ((sources & s) != 0) names.Add(Name(s));
            return names;
        }

        public static bool TryParse(string name, out TimeSources source)
        {
            foreach (var s in Each)
                if (string.Equals(Name(s), name, StringComparison.OrdinalIgnoreCase))
                {
                    source = s;
                    return true;
                }
            source = TimeSources.None;
            return false;
        }

        public static string NameList() => "\"timeline\", \"animator\", \"animation\", \"particles\"";
    }
}
