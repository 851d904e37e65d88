using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>straight alpha</b>: the colour of the anti-aliased edge pixels (0 &lt; alpha &lt; 255) is straight, not
    /// premultiplied by alpha (pixels.md §2: trainers composite rgb·a + background·(1 − a), so a premultiplied edge is
    /// darkened twice — the dark fringe). A straight edge pixel holds the covered surface's own colour, close to the
    /// interior next to it; a premultiplied one is that colour × alpha. Per edge pixel that has a background pixel
    /// (alpha 0) and an interior pixel (alpha 255) within <see cref="Radius"/>, on an alpha ramp towards it (<see cref="OnRamp"/>): L_in the luminance of its nearest
    /// interior pixel(s) carried out to the edge along the interior's gradient (<see cref="Interior"/>), L_e its own (linear light), and β = (L_in − L_e) / ((1 − α)·L_in), which is 0 for straight
    /// colour, 1 for colour premultiplied in linear light and above 1 for colour premultiplied in the sRGB bytes. The
    /// median β of a view is the statistic: robust to the edge pixels whose neighbour is another surface or shading.
    /// Motion blur: the sharp and the blurred image both count (difference matting un-premultiplies each).
    /// </summary>
    public sealed class StraightAlphaCheck : IViewCheck
    {
        public const string CheckName = "straight alpha";

        /// <summary>Median β above which a view's edges fit premultiplied colour better than straight: halfway between the two models.</summary>
        public const double MaxMedianBeta = 0.5;

        /// <summary>
        /// An edge pixel tells the two apart only where premultiplying would darken it by at least this much (linear
        /// luminance, (1 − α)·L_in): ~1/4 of mid-grey's 0.21. Below it, 8-bit rounding and shading differences between the
        /// edge and its neighbour are as large as the effect. A dark target has no such pixels, and both models look alike.
        /// </summary>
        public const double MinDarkening = 0.05;

        /// <summary>Edge pixels that can tell (see <see cref="MinDarkening"/>) a view needs to be judged, and the dataset to be judged at all.</summary>
        public const int MinPixels = 20;

        /// <summary>How far (pixels, square window) an edge pixel looks for background and interior: an anti-aliased edge is 1–2 px wide.</summary>
        const int Radius = 2;

        int _views, _judged, _bad, _pixels;
        readonly List<double> _medians = new List<double>();
        readonly List<double> _all = new List<double>();

        public string Name => CheckName;

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (!images.HasColour || images.Alpha == null || images.ColourImage == null) return;
            _views++;
            var betas = new List<double>();
            Collect(images.ColourImage, images.Alpha, betas);
            if (images.BlurredImage != null && images.BlurredAlpha != null) Collect(images.BlurredImage, images.BlurredAlpha, betas);
            _pixels += betas.Count;
            _all.AddRange(betas);
            if (betas.Count < MinPixels) return;
            _judged++;
            var median = CheckFigures.Median(betas);
            _medians.Add(median);
            if (median > MaxMedianBeta)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.FrameImageFile, view.Frame, "the anti-aliased edges are darker than the interior next to them in proportion to alpha (median β " +
                    DatasetCheckResult.Number(median, "0.00") + " over " + betas.Count + " edge pixels; 0 = straight colour, 1 = premultiplied): the colour is premultiplied by alpha, and trainers, which expect straight colour, will show dark fringes. Write colour divided by alpha (difference matting un-premultiplies it)."));
            }
        }

        /// <summary>Adds β of every edge pixel of one RGBA (or grey + alpha) image that can tell the models apart.</summary>
        static void Collect(PngImage image, byte[] alpha, List<double> betas)
        {
            int w = image.Width, h = image.Height;
            var luminance = Luminance(image);
            if (luminance == null) return;
            for (var y = Radius; y < h - Radius; y++)
                for (var x = Radius; x < w - Radius; x++)
                {
                    var p = y * w + x;
                    int a = alpha[p];
                    if (a == 0 || a == 255) continue;
                    var background = false;
                    int nearest = int.MaxValue, count = 0;
                    double sum = 0;
                    for (var dy = -Radius; dy <= Radius; dy++)
                        for (var dx = -Radius; dx <= Radius; dx++)
                        {
                            var q = p + dy * w + dx;
                            if (alpha[q] == 0) { background = true; continue; }
                            if (alpha[q] != 255) continue;
                            var d = dx * dx + dy * dy;
                            if (d > nearest) continue;
                            if (d < nearest) { nearest = d; sum = 0; count = 0; }
                            if (OnRamp(alpha, p, a, w, dx, dy)) { sum += Interior(luminance, alpha, w, h, x, y, dx, dy); count++; }
                        }
                    if (!background || count == 0) continue;
                    var inside = sum / count;
                    var darkening = (1 - a / 255.0) * inside;
                    if (darkening < MinDarkening) continue;
                    betas.Add((inside - luminance[p]) / darkening);
                }
        }

        /// <summary>
        /// True when alpha rises strictly through the pixel towards its interior neighbour at (dx, dy): each of the 8
        /// neighbours on the interior's side (a positive component along the step (sign dx, sign dy)) is more opaque and each
        /// on the other side less. A 2-pixel glass ring on a staircase diagonal still has a more opaque diagonal neighbour,
        /// but also a neighbour of its own alpha on the interior's side. An anti-aliased silhouette is such a ramp (coverage grows
        /// into the surface); a plateau of partial alpha — glass, a semi-transparent material, alpha 0.5 for several pixels
        /// between an opaque object and the background — is not, and its colour is its own surface's, not the interior's
        /// darkened: judged against the interior it read β 1.5 in straight colour (the check benchmark's point-sampled
        /// glass sphere, 16 of 300 views failed before this rule).
        /// </summary>
        static bool OnRamp(byte[] alpha, int p, int a, int w, int dx, int dy)
        {
            int sx = Math.Sign(dx), sy = Math.Sign(dy);
            for (var oy = -1; oy <= 1; oy++)
                for (var ox = -1; ox <= 1; ox++)
                {
                    var towards = ox * sx + oy * sy;
                    if (towards == 0) continue;
                    var q = alpha[p + oy * w + ox];
                    if (towards > 0 ? q <= a : q >= a) return false;
                }
            return true;
        }

        /// <summary>
        /// The interior's luminance carried out to the edge pixel (x, y) from its interior neighbour at (dx, dy): linearly
        /// extrapolated, 2·L₁ − L₂, from that neighbour and the next interior pixel the same step further in, when there is
        /// one (else L₁ itself); never below 0. Shading falls off towards a silhouette (Lambert at grazing angles): a lit
        /// sphere's rim pixel is darker than the pixel inside it in straight colour too. Against the neighbour alone such a
        /// rim read β 0.8–0.9 (a sphere of radius 25 and 100 px lit from the camera, no ambient light, straight colour), as
        /// much as premultiplied colour; against the extrapolation 0.28, or too dark to tell, while premultiplied colour
        /// still reads β 1.0 (prototype of this rule, 2026-12-06).
        /// </summary>
        static double Interior(float[] luminance, byte[] alpha, int w, int h, int x, int y, int dx, int dy)
        {
            var near = luminance[(y + dy) * w + x + dx];
            int x2 = x + 2 * dx, y2 = y + 2 * dy;
            if (x2 < 0 || y2 < 0 || x2 >= w || y2 >= h || alpha[y2 * w + x2] != 255) return near;
            return Math.Max(0, 2.0 * near - luminance[y2 * w + x2]);
        }

        /// <summary>Linear-light luminance (Rec. 709 weights) of each pixel, the PNG's values taken as sRGB; null for a layout without alpha.</summary>
        static float[] Luminance(PngImage image)
        {
            int channels = image.Channels, n = image.Width * image.Height;
            if (channels != 4 && channels != 2) return null;
            var bytes = image.BitDepth == 16 ? 2 : 1; // 16-bit: the high byte is precise enough for a ratio of 0 or 1
            var s = image.Samples;
            var stride = channels * bytes;
            var luminance = new float[n];
            for (int i = 0, j = 0; i < n; i++, j += stride)
                luminance[i] = channels == 2 ? Srgb.Decode(s[j])
                    : 0.2126f * Srgb.Decode(s[j]) + 0.7152f * Srgb.Decode(s[j + bytes]) + 0.0722f * Srgb.Decode(s[j + 2 * bytes]);
            return luminance;
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no colour image with an alpha channel could be decoded");
            if (_pixels < MinPixels)
                return DatasetCheckResult.Skip(Name, "cannot tell straight from premultiplied colour: " + _pixels + " edge pixels (0 < alpha < 255 between background and interior) where premultiplying would darken the luminance by ≥ " +
                    DatasetCheckResult.Number(MinDarkening, "0.00") + ", fewer than " + MinPixels + " (a dark or opaque-edged target looks alike either way, a solid background has no edges)");
            var figure = _pixels + " edge pixels in " + _views + " views, median β " + DatasetCheckResult.Number(CheckFigures.Median(_all), "0.00") +
                         " (0 = straight, 1 = premultiplied); " + _judged + " views judged" + (_judged > 0 ? ", worst median β " + DatasetCheckResult.Number(Max(_medians), "0.00") : "");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure,
                "median β ≤ " + DatasetCheckResult.Number(MaxMedianBeta, "0.0") + " per view with ≥ " + MinPixels + " telling edge pixels", _bad > 0 ? _bad + " problem(s)" : null);
        }

        static double Max(List<double> values)
        {
            var max = double.NegativeInfinity;
            foreach (var v in values) max = Math.Max(max, v);
            return max;
        }
    }
}
