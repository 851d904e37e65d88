using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The problems of the "flow" section (<see cref="SettingsValidator"/> adds them), each naming its key and the fix:
    /// flow needs a dynamic capture whose geometry pack holds the target at every step, a pinhole camera, spans of at
    /// least 1 and below the step count, query frames among the steps and a stride of at least 1.
    /// </summary>
    public static class FlowSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var f = settings?.Flow;
            if (f == null || !f.Enabled) return problems;
            if (settings.Time == null || !settings.Time.Enabled)
                problems.Add(new ValidationProblem("flow", "on", "needs a dynamic capture, but time.mode is \"static\": flow is the target's motion between time steps.",
                    "Set time.mode to \"monocular\" or \"multi-view\", or remove the \"flow\" section."));
            if (!settings.GeometryPack || !settings.GeometryPackEveryStep)
                problems.Add(new ValidationProblem("geometryPack", settings.GeometryPack ? "true" : "false",
                    "is not \"everyStep\", but flow is computed from the target's mesh at every time step.",
                    "Set \"geometryPack\": \"everyStep\", or remove the \"flow\" section."));
            if (settings.Lens != null && settings.Lens.Enabled)
                problems.Add(new ValidationProblem("lens", settings.Lens.Model,
                    "is not carried by flow yet: flow is computed for a pinhole camera.",
                    "Remove the \"lens\" section, or remove the \"flow\" section."));
            var steps = KnownSteps(settings);
            var spans = f.Spans ?? new int[0];
            if (spans.Length == 0 && (f.Forward || f.Backward))
                problems.Add(new ValidationProblem("flow.spans", "[]", "is empty, so no frame pair would get flow.",
                    "Give the step spans, e.g. [1] for each step and the next."));
            for (var i = 0; i < spans.Length; i++)
            {
                if (spans[i] < 1)
                    problems.Add(new ValidationProblem("flow.spans[" + i + "]", spans[i].ToString(CultureInfo.InvariantCulture),
                        "is below 1: a span is how many steps apart the two frames of a pair are.", "Use 1 (the next step) or more."));
                else if (steps.HasValue && spans[i] >= steps.Value)
                    problems.Add(new ValidationProblem("flow.spans[" + i + "]", spans[i].ToString(CultureInfo.InvariantCulture),
                        "is not below the " + steps.Value + " time steps, so no two frames are that far apart.", "Use a span from 1 to " + (steps.Value - 1) + "."));
                else if (Array.IndexOf(spans, spans[i]) < i)
                    problems.Add(new ValidationProblem("flow.spans[" + i + "]", spans[i].ToString(CultureInfo.InvariantCulture),
                        "is given twice.", "List each span once."));
            }
            if (!f.Forward && !f.Backward && (f.TrackQueryFrames == null || f.TrackQueryFrames.Length == 0))
                problems.Add(new ValidationProblem("flow.forward", "false", "and flow.backward are both false and no tracks are asked for, so nothing would be written.",
                    "Set \"forward\": true, or remove the \"flow\" section."));
            var queries = f.TrackQueryFrames ?? new int[0];
            for (var i = 0; i < queries.Length; i++)
            {
                if (queries[i] < 0 || steps.HasValue && queries[i] >= steps.Value)
                    problems.Add(new ValidationProblem("flow.tracks.queryFrames[" + i + "]", queries[i].ToString(CultureInfo.InvariantCulture),
                        "is not a frame of the videos" + (steps.HasValue ? " (0 to " + (steps.Value - 1) + ", one per time step)." : " (0 or more, one per time step)."),
                        "Use a frame index from 0 to the number of time steps − 1."));
                else if (Array.IndexOf(queries, queries[i]) < i)
                    problems.Add(new ValidationProblem("flow.tracks.queryFrames[" + i + "]", queries[i].ToString(CultureInfo.InvariantCulture),
                        "is given twice.", "List each query frame once."));
            }
            if (f.TrackStride < 1)
                problems.Add(new ValidationProblem("flow.tracks.stride", f.TrackStride.ToString(CultureInfo.InvariantCulture),
                    "is below 1: the query points are every stride-th pixel across and down.", "Use 1 (every pixel) or more, e.g. 8."));
            return problems;
        }

        /// <summary>The capture's step count (each video's frame count) when the settings alone fix it; null when a clip's length decides.</summary>
        public static int? KnownSteps(DatasetSettings settings)
        {
            var time = settings.Time;
            if (time == null || !time.Enabled || time.EndAtClipLength) return null;
            if (time.Fps > 0)
            {
                var span = time.EndSeconds - time.StartSeconds;
                if (!(span > 0) || double.IsInfinity(span)) return null;
                var frames = Math.Floor(span * time.Fps + 1e-9);
                return frames >= TimeSettings.MaxSteps ? (int?)null : (int)frames + 1;
            }
            if (time.Mode == TimeMode.Monocular && time.Steps == 0) return settings.Train?.Count;
            return time.Steps >= 2 ? (int?)time.Steps : null;
        }
    }
}
