using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The times at which an animated camera is sampled: <c>samples</c> times spread evenly over [start, end], both
    /// ends included (one sample: the start), or every k-th frame from the start frame while it is not past the
    /// end — BlenderNeRF's "subset of frames" (frame_start to frame_end by frame_step). A frame f is at f / rate
    /// seconds, so with a step the times are start + i·k / rate, exact multiples of the frame time and never
    /// drifting through repeated addition.
    /// </summary>
    public static class AnimatedCameraSampling
    {
        /// <summary>Frames per second for a frame step when the clip gives none (a Timeline read without its package).</summary>
        public const double DefaultFrameRate = 60;

        /// <summary>The sample times in seconds; <paramref name="end"/> must already be resolved (the clip's end when the settings say 0).</summary>
        public static double[] Times(double start, double end, int samples, int frameStep, double frameRate, string fieldPrefix = "source")
        {
            var problems = Validate(fieldPrefix, samples, frameStep, frameRate, start, end);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            if (!(end >= start))
                throw new InvalidParameterException(new[] { RangeProblem(fieldPrefix, start, end) });
            if (frameStep > 0)
            {
                var rate = frameRate > 0 ? frameRate : DefaultFrameRate;
                // Tolerate a last frame that lands on the end within rounding (end = 2 s at 30 fps is frame 60).
                var frames = (long)Math.Floor((end - start) * rate / frameStep + 1e-9) + 1;
                if (frames > DatasetSettings.MaxViews)
                    throw new InvalidParameterException(new[]
                    {
                        new ValidationProblem(fieldPrefix + ".frameStep", frameStep.ToString(System.Globalization.CultureInfo.InvariantCulture),
                            "gives " + frames.ToString(System.Globalization.CultureInfo.InvariantCulture) + " views over " + ValidationProblem.Format(end - start) + " s at " +
                            ValidationProblem.Format(rate) + " frames per second, more than " + DatasetSettings.MaxViews.ToString(System.Globalization.CultureInfo.InvariantCulture) + ".",
                            "Use a larger frame step or a shorter range."),
                    });
                var stepped = new double[frames];
                for (var i = 0; i < frames; i++) stepped[i] = start + i * frameStep / rate;
                return stepped;
            }
            var times = new double[samples];
            for (var i = 0; i < samples; i++) times[i] = samples == 1 ? start : start + (end - start) * i / (samples - 1);
            return times;
        }

        /// <summary>The range [start, end] a source samples: its own end, or the clip's length when it gives none.</summary>
        public static double ResolveEnd(double end, double clipLength) => end > 0 ? end : clipLength;

        public static IReadOnlyList<ValidationProblem> Validate(string fieldPrefix, int samples, int frameStep, double frameRate, double start, double end)
        {
            var problems = new List<ValidationProblem>();
            if (frameStep == 0)
            {
                var p = ValidationProblem.OutsideRange(fieldPrefix + ".samples", samples, 1, DatasetSettings.MaxViews);
                if (p != null) problems.Add(p);
            }
            else if (frameStep < 0)
                problems.Add(new ValidationProblem(fieldPrefix + ".frameStep", frameStep.ToString(System.Globalization.CultureInfo.InvariantCulture),
                    "is negative.", "Use 0 to spread \"samples\" views evenly, or k ≥ 1 for every k-th frame."));
            if (double.IsNaN(frameRate) || double.IsInfinity(frameRate) || frameRate < 0 || frameRate > 1000)
                problems.Add(ValidationProblem.OutsideRange(fieldPrefix + ".frameRate", frameRate, 0, 1000, "frames per second (0: the clip's)"));
            if (double.IsNaN(start) || double.IsInfinity(start) || start < 0)
                problems.Add(new ValidationProblem(fieldPrefix + ".start", ValidationProblem.Format(start), "must be a time of 0 seconds or more.", "Use e.g. 0 for the clip's start."));
            if (double.IsNaN(end) || double.IsInfinity(end) || (end > 0 && end < start))
                problems.Add(RangeProblem(fieldPrefix, start, end));
            return problems;
        }

        static ValidationProblem RangeProblem(string fieldPrefix, double start, double end) =>
            new ValidationProblem(fieldPrefix + ".end", ValidationProblem.Format(end), "is before the start (" + ValidationProblem.Format(start) + " s).",
                "Use an end after the start, or 0 for the end of the clip or Timeline.");
    }
}
