using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>exposure</b>: frames that record <c>exposure_ev</c> and <c>white_balance</c> hold finite values in the settings'
    /// range, on every frame of their split or none; where the frame names its unmodified image (<c>clean_path</c>), the
    /// colour image is that image times 2^EV · gain per channel in linear light, clipped at 1, with the same alpha
    /// (Documentation~/exposure.md). The comparison allows exactly the 8-bit rounding: a clean byte b stands for any linear
    /// value between the decodes of b ± ½, and the modified byte must be the encoding of that interval times the gain
    /// (a clean 255 may have been clipped, so it only bounds from below). A gain applied to the sRGB values, gains swapped
    /// between channels or the EV's sign flipped fall outside it; the problem says which scale the pixels show.
    /// </summary>
    public sealed class ExposureCheck : IViewCheck
    {
        /// <summary>Share of a view's colour samples that may fall outside the rounding interval (none do in our writer's output).</summary>
        public const double MaxMismatch = 0.001;

        public string Name => "exposure";

        readonly string _root;
        readonly Dictionary<string, (int with, int without)> _counts = new Dictionary<string, (int, int)>();
        int _recorded, _compared, _bad;
        double _worst;

        public ExposureCheck(string root) { _root = root; }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (!images.HasColour) return;
            var frame = view.Source;
            if (frame == null) return;
            // The frame's own image (file_path), whose clean image clean_path names; with motion blur ColourFile is the sharp one.
            var image = view.FrameImageFile;
            var file = "./" + image;
            var read = frame.Exposure;
            var hasEv = read.HasEv;
            var hasWb = read.HasWhiteBalance;
            _counts.TryGetValue(view.Split, out var count);
            _counts[view.Split] = hasEv || hasWb ? (count.with + 1, count.without) : (count.with, count.without + 1);
            if (!hasEv && !hasWb) return;
            _recorded++;
            if (!(read.Values is ViewExposure exposure))
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, read.Problem));
                _bad++;
                return;
            }
            var cleanFile = frame.Named(ExposureKeys.CleanPath);
            if (cleanFile == null) return;
            var clean = cleanFile.Written;
            var relative = cleanFile.Relative;
            if (!cleanFile.Exists)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, ExposureKeys.CleanPath + " names " + clean + ", which is not a file inside the dataset."));
                _bad++;
                return;
            }
            PngImage modified, unmodified;
            try
            {
                modified = PngReader.Read(Path.Combine(_root, image));
                unmodified = PngReader.Read(Path.Combine(_root, relative));
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, "the image or its clean image cannot be decoded: " + e.Message));
                _bad++;
                return;
            }
            if (modified.BitDepth != 8 || unmodified.BitDepth != 8 || modified.Channels != unmodified.Channels || modified.Channels < 3
                || modified.Width != unmodified.Width || modified.Height != unmodified.Height)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, "and its clean image " + clean + " differ in size or layout (" +
                    Layout(modified) + " vs " + Layout(unmodified) + "); both are 8-bit RGB(A) of one size."));
                _bad++;
                return;
            }
            _compared++;
            var outside = Compare(modified, unmodified, exposure, out var alphaDiffers);
            var share = outside / (3.0 * modified.Width * modified.Height);
            if (share > _worst) _worst = share;
            if (share > MaxMismatch)
            {
                var measured = MeasuredScales(modified, unmodified);
                problems.Add(new DatasetProblem(Name, file, view.Frame, CheckFigures.Percent(share) + " of the colour samples are not " + clean +
                    " × 2^exposure_ev × white_balance in linear light (exposure_ev " + DatasetCheckResult.Number(exposure.Ev) + ", white_balance [" +
                    Triple(exposure.R, exposure.G, exposure.B) + "] give the linear scales [" + Triple(exposure.Scale(0), exposure.Scale(1), exposure.Scale(2)) +
                    "]; the pixels show about [" + Triple(measured[0], measured[1], measured[2]) + "]): the gain was applied to sRGB values, to the wrong channels or with the wrong sign, or the recorded values are not the applied ones."));
                _bad++;
            }
            if (alphaDiffers)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, "its alpha differs from " + clean + "'s; exposure and white balance leave alpha unchanged."));
                _bad++;
            }
        }

        public DatasetCheckResult Finish()
        {
            if (_recorded == 0) return DatasetCheckResult.Skip(Name, "no frame records " + ExposureKeys.Ev + ": exposure is off");
            // Some frames of a split with the keys and others without: a writer that lost them on some views.
            var mixed = new List<string>();
            foreach (var pair in _counts)
                if (pair.Value.with > 0 && pair.Value.without > 0) mixed.Add(pair.Key);
            _bad += mixed.Count;
            var figure = _recorded + " views record exposure" + (_compared > 0
                ? "; " + _compared + " compared with their clean image, worst " + CheckFigures.Percent(_worst) + " of samples outside the rounding interval"
                : " (no clean images: values checked, pixels not compared)") +
                (mixed.Count > 0 ? "; split(s) " + string.Join(", ", mixed) + " record it on some frames only" : "");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure,
                "exposure_ev in ±" + ExposureSettings.MaxEv + ", white_balance gains in [1/16, 16], on all frames of a split or none; ≤ " +
                CheckFigures.Percent(MaxMismatch) + " of samples off clean × gain", _bad > 0 ? _bad + " problem(s)" : null);
        }

        /// <summary>The colour samples of <paramref name="modified"/> (8-bit RGB or RGBA) outside the rounding interval of <paramref name="clean"/> × the scales.</summary>
        public static int SamplesOutside(PngImage modified, PngImage clean, ViewExposure exposure) => Compare(modified, clean, exposure, out _);

        /// <summary>Colour samples outside the rounding interval of clean × scale, and whether alpha differs.</summary>
        static int Compare(PngImage modified, PngImage clean, ViewExposure exposure, out bool alphaDiffers)
        {
            int channels = modified.Channels, n = modified.Width * modified.Height;
            byte[] m = modified.Samples, c = clean.Samples;
            // One table per bound, channel k at k·256 (a flat array keeps the inner loop to plain indexing on Mono).
            var lowest = new byte[768];
            var highest = new byte[768];
            for (var k = 0; k < 3; k++) Interval(exposure.Scale(k), lowest, highest, k * 256);
            var outside = 0;
            alphaDiffers = false;
            for (int i = 0, at = 0; i < n; i++, at += channels)
            {
                int r = c[at], g = 256 + c[at + 1], b = 512 + c[at + 2];
                byte vr = m[at], vg = m[at + 1], vb = m[at + 2];
                if (vr < lowest[r] || vr > highest[r]) outside++;
                if (vg < lowest[g] || vg > highest[g]) outside++;
                if (vb < lowest[b] || vb > highest[b]) outside++;
                if (channels == 4 && m[at + 3] != c[at + 3]) alphaDiffers = true;
            }
            return outside;
        }

        /// <summary>
        /// For a failure's message: per channel, the median ratio of modified to clean linear values over mid-tones that are
        /// neither clipped nor near black — the scale the pixels show.
        /// </summary>
        static double[] MeasuredScales(PngImage modified, PngImage clean)
        {
            int channels = modified.Channels, n = modified.Width * modified.Height;
            byte[] m = modified.Samples, c = clean.Samples;
            var measured = new double[3];
            for (var k = 0; k < 3; k++)
            {
                var ratios = new List<double>();
                for (int i = 0, at = k; i < n; i += 7, at += 7 * channels)
                {
                    byte b = c[at], v = m[at];
                    if (b >= 40 && b <= 200 && v < 250 && v > 0) ratios.Add(Srgb.DecodeExact(v / 255.0) / Srgb.DecodeExact(b / 255.0));
                }
                measured[k] = ratios.Count == 0 ? double.NaN : CheckFigures.Median(ratios);
            }
            return measured;
        }

        /// <summary>Per clean byte b, the lowest and highest modified byte consistent with some linear value that rounds to b.</summary>
        static void Interval(double scale, byte[] lowest, byte[] highest, int at)
        {
            for (var b = 0; b < 256; b++)
            {
                var lo = b == 0 ? 0 : Srgb.DecodeExact((b - 0.5) / 255);
                lowest[at + b] = Srgb.EncodeByteExact(ExposureWhiteBalance.Apply(lo, scale));
                // A clean 255 may be a clipped brighter value: it bounds the modified byte from below only.
                highest[at + b] = b == 255 ? (byte)255 : Srgb.EncodeByteExact(ExposureWhiteBalance.Apply(Srgb.DecodeExact((b + 0.5) / 255), scale));
            }
        }

        static string Layout(PngImage png) => png.Width + "×" + png.Height + " " + png.BitDepth + "-bit, " + png.Channels + " channel(s)";

        internal static string Triple(double a, double b, double c) =>
            DatasetCheckResult.Number(a, "0.###") + ", " + DatasetCheckResult.Number(b, "0.###") + ", " + DatasetCheckResult.Number(c, "0.###");

    }
}
