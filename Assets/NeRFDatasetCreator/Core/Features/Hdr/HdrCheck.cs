using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>hdr</b>: where a frame names its linear colour (<c>hdr_path</c>), that EXR encoded as the PNG is made — colour
    /// clipped to [0, 1] (then, on a frame with exposure and no clean image, times 2^exposure_ev · white_balance and
    /// clipped again), sRGB-encoded to the nearest byte; alpha as round(255·a) — is the frame's PNG within
    /// <see cref="ToleranceCodes"/> code on every covered sample (PNG alpha &gt; 0), allowing <see cref="MaxMismatch"/> of
    /// them beyond (float rounding at a code boundary). A frame with exposure and a clean image (<c>clean_path</c>) is
    /// compared with the clean image. An EXR that was scaled, gamma-encoded, tone-mapped or belongs to another view
    /// falls far outside.
    /// </summary>
    public sealed class HdrCheck : IViewCheck
    {
        /// <summary>The PNG and the encoded EXR are made by the same float arithmetic; one code covers rounding differences.</summary>
        public const int ToleranceCodes = 1;

        /// <summary>Share of a view's covered colour samples that may differ by more than <see cref="ToleranceCodes"/>.</summary>
        public const double MaxMismatch = 0.001;

        public string Name => "hdr";

        readonly string _root;
        int _views, _bad;
        double _worst, _brightest;
        int _largest;

        public HdrCheck(string root) { _root = root; }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            var frame = view.Source;
            var hdr = frame?.Named(HdrKeys.HdrPath);
            if (hdr == null) return;
            var image = view.FrameImageFile;
            var file = "./" + image;
            if (!hdr.Exists)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, HdrKeys.HdrPath + " names " + hdr.Written + ", which is not a file inside the dataset."));
                _bad++;
                return;
            }
            var scale = new[] { 1.0, 1.0, 1.0 };
            var against = image;
            var exposure = frame.Exposure.Values;
            if (exposure is ViewExposure e)
            {
                var clean = frame.Named(ExposureKeys.CleanPath);
                if (clean != null && clean.Exists) against = clean.Relative;
                else scale = new[] { e.Scale(0), e.Scale(1), e.Scale(2) };
            }
            ExrImage exr;
            PngImage png;
            try
            {
                exr = ExrReader.Read(Path.Combine(_root, hdr.Relative));
                png = PngReader.Read(Path.Combine(_root, against));
            }
            catch (Exception ex) when (ex is InvalidDataException || ex is IOException || ex is UnauthorizedAccessException)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, HdrKeys.HdrPath + " or the image cannot be decoded: " + ex.Message));
                _bad++;
                return;
            }
            float[] r = exr.Channel("R"), g = exr.Channel("G"), b = exr.Channel("B"), a = exr.Channel("A");
            if (r == null || g == null || b == null || a == null || exr.Width != png.Width || exr.Height != png.Height || png.BitDepth != 8 || png.Channels < 3)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, hdr.Written + " is " + exr.Width + "×" + exr.Height + " with channels " + string.Join("", exr.Channels.Keys) +
                    ", the image " + png.Width + "×" + png.Height + " " + png.BitDepth + "-bit with " + png.Channels + " channels; the HDR image is R G B A floats of the image's size."));
                _bad++;
                return;
            }
            _views++;
            int n = png.Width * png.Height, channels = png.Channels, covered = 0, outside = 0, largest = 0;
            var samples = png.Samples;
            for (int i = 0, at = 0; i < n; i++, at += channels)
            {
                var alpha = channels == 4 ? samples[at + 3] : 255;
                if (alpha == 0) continue;
                covered++;
                var values = new[] { r[i], g[i], b[i] };
                for (var c = 0; c < 3; c++)
                {
                    if (values[c] > _brightest) _brightest = values[c];
                    var encoded = Srgb.EncodeByteExact(Math.Min(1.0, Math.Min(1.0, values[c]) * scale[c]));
                    var difference = Math.Abs(encoded - samples[at + c]);
                    if (difference > largest) largest = difference;
                    if (difference > ToleranceCodes) outside++;
                }
                if (channels == 4)
                {
                    var difference = Math.Abs((int)Math.Floor(a[i] * 255.0 + 0.5) - alpha);
                    if (difference > largest) largest = difference;
                    if (difference > ToleranceCodes) outside++;
                }
            }
            var share = covered == 0 ? 0 : outside / ((channels == 4 ? 4.0 : 3.0) * covered);
            if (share > _worst) _worst = share;
            if (largest > _largest) _largest = largest;
            if (share > MaxMismatch)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, CheckFigures.Percent(share) + " of the covered samples of " + hdr.Written +
                    ", clipped and sRGB-encoded, differ from " + (against == image ? "the image" : against) + " by more than " + ToleranceCodes + " code (up to " + largest +
                    "): the EXR is not this view's linear colour (scaled, gamma-encoded, tone-mapped or another view's?)."));
                _bad++;
            }
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0 && _bad == 0) return DatasetCheckResult.Skip(Name, "no frame names " + HdrKeys.HdrPath + ": hdr is off");
            var figure = _views + " HDR images compared with their PNGs; worst " + CheckFigures.Percent(_worst) + " of covered samples beyond " + ToleranceCodes +
                " code (largest difference " + _largest + "); brightest linear value " + DatasetCheckResult.Number(_brightest);
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure,
                "hdr_path clipped and encoded = the PNG within " + ToleranceCodes + " code on ≥ " + CheckFigures.Percent(1 - MaxMismatch) + " of covered samples",
                _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
