using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What colour the renders show where the ground truth is fully transparent (alpha 0) — the background the model
    /// was trained or rendered over — measured on up to <see cref="Views"/> views spread over the split before anything
    /// is written. When it is clearly another colour than the one chosen for scoring (issue 35: white-background renders
    /// scored with <c>--background black</c> lost 0.85 dB silently), <see cref="Problem"/> names the colour.
    /// </summary>
    public static class RenderBackgroundCheck
    {
        public const int Views = 3;

        /// <summary>Fewer transparent pixels than this say nothing about the background.</summary>
        public const long MinimumPixels = 64;

        /// <summary>A mean farther than this (largest channel difference, in [0, 1]) from the chosen colour is another background; floaters move it far less.</summary>
        public const double Tolerance = 0.2;

        public sealed class Measurement
        {
            public double R, G, B;
            public long Pixels;
            public int ViewsMeasured;
        }

        /// <summary>The mean render colour over the ground truth's alpha-0 pixels of up to <see cref="Views"/> views; null when the ground truth has no alpha.</summary>
        public static Measurement Measure(EvaluationDataset dataset, RenderSet renders, EvaluationBackground background, int firstColumn)
        {
            var views = renders.Views.Count;
            if (views == 0) return null;
            var picked = Enumerable.Range(0, Math.Min(Views, views)).Select(k => renders.Views[(int)((long)k * views / Math.Min(Views, views))]).Distinct().ToList();
            double r = 0, g = 0, b = 0;
            long n = 0;
            var measured = 0;
            foreach (var view in picked)
            {
                var truth = TrainTestExposureCrop.Columns(PngReader.Read(dataset.Frames[view.FrameIndex].ImagePath), firstColumn);
                if (truth.Channels != 2 && truth.Channels != 4) return null;
                var render = EvaluationImages.Colour(PngReader.Read(view.ColourPath), background, view.ColourPath);
                if (render.Length != truth.Width * truth.Height * 3) continue; // another size: CheckSizes has refused it already
                var wide = truth.BitDepth == 16;
                var channels = truth.Channels;
                for (var p = 0; p < truth.Width * truth.Height; p++)
                {
                    var at = (p * channels + channels - 1) * (wide ? 2 : 1);
                    var alpha = wide ? truth.Samples[at] | truth.Samples[at + 1] : truth.Samples[at];
                    if (alpha != 0) continue;
                    r += render[3 * p];
                    g += render[3 * p + 1];
                    b += render[3 * p + 2];
                    n++;
                }
                measured++;
            }
            return n == 0 ? new Measurement { ViewsMeasured = measured } : new Measurement { R = r / n, G = g / n, B = b / n, Pixels = n, ViewsMeasured = measured };
        }

        /// <summary>
        /// Why the renders' background is not <paramref name="background"/>, naming their colour; null when it is (or
        /// cannot be told: too few transparent pixels, a background without a colour).
        /// </summary>
        public static string Problem(Measurement m, EvaluationBackground background, DatasetConfig config)
        {
            if (m == null || m.Pixels < MinimumPixels || !background.Known) return null;
            var distance = Math.Max(Math.Abs(m.R - background.R), Math.Max(Math.Abs(m.G - background.G), Math.Abs(m.B - background.B)));
            if (distance <= Tolerance) return null;
            return "where the ground truth is transparent (" + m.Pixels.ToString(CultureInfo.InvariantCulture) + " pixels in " + m.ViewsMeasured + " views) the renders are " +
                   Name(m, config) + " (mean " + F(m.R) + ", " + F(m.G) + ", " + F(m.B) + "), not " + background.Name +
                   ": the model was trained or rendered over that colour, and scored over " + background.Name + " its background would count as error.";
        }

        /// <summary>The colour a measurement is nearest, when it is near one: white, black, the dataset's own, or nerfstudio splatfacto's evaluation colour.</summary>
        public static string Name(Measurement m, DatasetConfig config)
        {
            var known = new List<(string, double, double, double)>
            {
                ("white", 1, 1, 1),
                ("black", 0, 0, 0),
                // splatfacto.py (nerfstudio 50e0e3c) lines 247–250: background_color "random" evaluates over viser's default colour.
                ("nerfstudio splatfacto's evaluation colour for a random background", 0.1490, 0.1647, 0.2157),
            };
            var own = config?.Background;
            if (own != null && !own.Transparent && !own.Sky) known.Add(("the dataset's own " + own.ToConfigString(), own.R, own.G, own.B));
            foreach (var (name, r, g, b) in known)
                if (Math.Max(Math.Abs(m.R - r), Math.Max(Math.Abs(m.G - g), Math.Abs(m.B - b))) <= 0.08) return name;
            return "another colour";
        }

        static string F(double v) => v.ToString("0.000", CultureInfo.InvariantCulture);
    }
}
