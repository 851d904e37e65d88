using System;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame keys of a view with exposure and white balance. No loader reads per-frame exposure from a
    /// transforms file (nerfstudio, instant-ngp and gsplat were searched; Documentation~/maintainers/exposure.md), so
    /// the names are ours, in the snake_case of the other per-frame keys.
    /// </summary>
    public static class ExposureKeys
    {
        /// <summary>The view's exposure and white balance in a transforms frame, when <paramref name="exposure"/> modifies its split.</summary>
        internal static void WriteFrame(TransformsFramesText frame, PlannedView v, ExposurePlan exposure)
        {
            if (exposure == null || !exposure.Applies(v.Split)) return;
            var e = exposure.For(v.Split, v.Index);
            frame.NumberKey(Ev, e.Ev);
            frame.TripleKey(WhiteBalance, e.R, e.G, e.B);
        }

        /// <summary>The view's unmodified image's key, when it is written.</summary>
        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v) => frame.FileKey(v, DatasetFileKind.CleanColor, CleanPath);

        /// <summary>The view's exposure in stops (a number).</summary>
        public const string Ev = "exposure_ev";

        /// <summary>The view's white-balance gains, a list [r, g, b] of linear multipliers.</summary>
        public const string WhiteBalance = "white_balance";

        /// <summary>The unmodified image, <c>./train/r_7_clean.png</c>, when it is written.</summary>
        public const string CleanPath = "clean_path";

        /// <summary>
        /// Reads a frame's exposure keys (<see cref="DatasetFolder"/> calls it for every frame): the values when usable,
        /// else why not. <c>clean_path</c> is a file key, resolved with the frame's other files.
        /// </summary>
        public static FrameExposure Read(JObject frame)
        {
            var evToken = frame?[Ev];
            var wbToken = frame?[WhiteBalance];
            if (evToken == null && wbToken == null) return FrameExposure.None;
            var read = new FrameExposure { HasEv = evToken != null, HasWhiteBalance = wbToken != null };
            if (!JsonValues.TryNumber(evToken, out var ev) || double.IsNaN(ev) || double.IsInfinity(ev))
            {
                read.Problem = Ev + " is " + Describe(evToken) + ", not a finite number of stops (it is written with " + WhiteBalance + ").";
                return read;
            }
            if (Math.Abs(ev) > ExposureSettings.MaxEv)
            {
                read.Problem = Ev + " " + DatasetCheckResult.Number(ev) + " is outside ±" + ExposureSettings.MaxEv + " stops.";
                return read;
            }
            var gains = new double[3];
            if (!(wbToken is JArray wb) || wb.Count != 3
                || !JsonValues.TryNumber(wb[0], out gains[0]) || !JsonValues.TryNumber(wb[1], out gains[1]) || !JsonValues.TryNumber(wb[2], out gains[2]))
            {
                read.Problem = WhiteBalance + " is " + Describe(wbToken) + ", not three gains [r, g, b].";
                return read;
            }
            foreach (var g in gains)
                if (!(g >= ExposureSettings.MinGain && g <= ExposureSettings.MaxGain))
                {
                    read.Problem = WhiteBalance + " [" + ExposureCheck.Triple(gains[0], gains[1], gains[2]) + "] has a gain outside [1/16, 16].";
                    return read;
                }
            read.Values = new ViewExposure(ev, gains[0], gains[1], gains[2]);
            return read;
        }

        static string Describe(JToken t) => t == null ? "missing" : t.ToString(Formatting.None);
    }
}
