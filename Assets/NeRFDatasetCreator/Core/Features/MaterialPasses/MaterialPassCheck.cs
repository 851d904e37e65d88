using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>materials</b>: per view whose frame names material passes (<see cref="MaterialKeys"/>), each pass's EXR (the
    /// truth) and PNG hold what Documentation~/output-format.md says:
    /// <list type="bullet">
    /// <item>coverage: each file's alpha is the colour image's alpha (exactly; not compared over a solid background,
    /// whose colour image is opaque), the EXR's A is the PNG's A / 255, RGB is 0 where alpha is 0, and no pixel is whole
    /// (255) in one of alpha and mask and empty in the other (at most <see cref="MaxCoverageMismatch"/> of them); the
    /// coverage PNG is 0 where the mask is 0 (the same share allowed, for a lens's resampled edges);</item>
    /// <item>metallic and roughness lie in [0, 1] and are grey (R = G = B in both files): a map packed or swapped into
    /// another channel fails;</item>
    /// <item>the PNG is the EXR encoded as dataset_config.json's <c>materials.encodings</c> records (sRGB for colours,
    /// linear for scalars when it records nothing), within <see cref="ToleranceCodes"/> code on all but
    /// <see cref="MaxMismatch"/> of the covered samples: an sRGB-encoded linear map, a linear-encoded colour map or
    /// colour channels in another order fall far outside, and the problem says which encoding the PNG matches instead.</item>
    /// </list>
    /// </summary>
    public sealed class MaterialPassCheck : IViewCheck
    {
        /// <summary>The PNG and the encoded EXR come from the same floats; one code covers rounding at a code boundary.</summary>
        public const int ToleranceCodes = 1;

        /// <summary>Share of a pass's covered samples that may differ from the encoded EXR by more than <see cref="ToleranceCodes"/>.</summary>
        public const double MaxMismatch = 0.001;

        /// <summary>Share of a view's covered pixels where the material alpha and the mask may disagree on coverage (edge rounding).</summary>
        public const double MaxCoverageMismatch = 0.005;

        public string Name => "materials";

        readonly string _root;
        readonly JObject _config;
        readonly bool _opaque;
        int _views, _files, _bad;
        double _worst;
        int _largest;

        /// <param name="config">The dataset's dataset_config.json (its <c>materials</c> record and background), or null.</param>
        public MaterialPassCheck(string root, DatasetConfig config)
        {
            _root = root;
            _config = config?.Json;
            _opaque = config?.OpaqueBackground == true;
        }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            var materials = view.Source?.Materials;
            if (materials == null || !materials.Any || !images.HasColour) return;
            _views++;
            var file = "./" + view.ColourFile;
            int width = images.Width, height = images.Height;
            // Over a solid background the colour image is opaque by design; the passes still carry coverage.
            var colourAlpha = _opaque ? null : images.Alpha;
            var first = true;
            foreach (var files in materials.Passes)
            {
                var pass = files.Pass;
                var exr = ReadExr(files.Exr, pass, view, width, height, problems);
                var png = pass.Png == null ? null : ReadPng(files.Png, pass, view, width, height, problems);
                if (exr == null || (pass.Png != null && png == null)) continue;
                _files++;
                var encoding = Encoding(pass, view, problems);
                if (encoding == null) continue;
                Compare(view, file, pass, exr, png, encoding.Value, colourAlpha, first ? images.Mask : null, problems);
                first = false;
            }
            if (materials.Coverage != null) CheckCoverage(view, file, materials.Coverage, images, problems);
        }

        void Compare(CheckView view, string file, MaterialPass pass, ExrImage exr, PngImage png, MaterialPngEncoding encoding, byte[] colourAlpha, byte[] mask,
            List<DatasetProblem> problems)
        {
            float[] r = exr.Channel("R"), g = exr.Channel("G"), b = exr.Channel("B"), a = exr.Channel("A");
            var samples = png?.Samples;
            var other = encoding == MaterialPngEncoding.Srgb ? MaterialPngEncoding.Linear : MaterialPngEncoding.Srgb;
            int n = exr.Width * exr.Height, covered = 0, alphaOff = 0, colourOff = 0, lit = 0, notGrey = 0, outside = 0, off = 0, offOther = 0, largest = 0, coverageOff = 0, either = 0;
            float lowest = 0, highest = 0;
            for (var i = 0; i < n; i++)
            {
                var alpha = samples != null ? samples[i * 4 + 3] : AlphaByte(a[i]);
                if (samples != null && AlphaByte(a[i]) != alpha) alphaOff++;
                if (colourAlpha != null && colourAlpha[i] != alpha) colourOff++;
                if (mask != null && (mask[i] > 0 || alpha > 0))
                {
                    // Only where one says "whole" and the other "nothing": the edges of alpha and mask differ by design
                    // (the alpha vs mask check holds them), most of all through a lens's resampling.
                    either++;
                    if ((mask[i] == 255 && alpha == 0) || (alpha == 255 && mask[i] == 0)) coverageOff++;
                }
                if (alpha == 0)
                {
                    if (r[i] != 0 || g[i] != 0 || b[i] != 0 || (samples != null && (samples[i * 4] | samples[i * 4 + 1] | samples[i * 4 + 2]) != 0)) lit++;
                    continue;
                }
                covered++;
                if (pass.Grey)
                {
                    if (r[i] != g[i] || r[i] != b[i] || (samples != null && (samples[i * 4] != samples[i * 4 + 1] || samples[i * 4] != samples[i * 4 + 2]))) notGrey++;
                    if (!(r[i] >= 0 && r[i] <= 1))
                    {
                        outside++;
                        if (!(r[i] >= lowest)) lowest = r[i];
                        if (!(r[i] <= highest)) highest = r[i];
                    }
                }
                if (samples == null) continue;
                var values = new[] { r[i], g[i], b[i] };
                bool beyond = false, beyondOther = false;
                for (var c = 0; c < 3; c++)
                {
                    var difference = Math.Abs(Encode(values[c], encoding) - samples[i * 4 + c]);
                    if (difference > largest) largest = difference;
                    if (difference > ToleranceCodes) beyond = true;
                    if (Math.Abs(Encode(values[c], other) - samples[i * 4 + c]) > ToleranceCodes) beyondOther = true;
                }
                if (beyond) off++;
                if (beyondOther) offOther++;
            }
            var files = pass.Png == null ? Path.GetFileName(view.Source.FileKey(pass.Key)) : pass.Key + "'s PNG and EXR";
            void Fail(string text)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, pass.Name + ": " + text));
                _bad++;
            }
            if (alphaOff > 0) Fail(alphaOff + " pixel(s) of the EXR's A are not the PNG's alpha / 255: the two files are not one image.");
            if (colourOff > 0) Fail(colourOff + " pixel(s) of " + files + " have another alpha than the colour image: a material pass's alpha is the colour image's coverage.");
            if (either > 0 && coverageOff > MaxCoverageMismatch * either)
                Fail(CheckFigures.Percent(coverageOff / (double)either) + " of the covered pixels are whole in the pass and empty in the mask or the other way round (at most " +
                     CheckFigures.Percent(MaxCoverageMismatch) + "): the pass belongs to another view or was not rendered with the target's coverage.");
            if (lit > 0) Fail(lit + " pixel(s) with alpha 0 have RGB other than 0: outside the coverage a pass is (0, 0, 0, 0).");
            if (notGrey > 0) Fail(notGrey + " covered pixel(s) are not grey (R = G = B): a scalar map packed or swapped into another channel?");
            if (outside > 0)
                Fail(outside + " covered pixel(s) lie outside [0, 1] (from " + DatasetCheckResult.Number(lowest) + " to " + DatasetCheckResult.Number(highest) + "): " + pass.Name + " is a fraction.");
            var share = covered == 0 ? 0 : off / (double)covered;
            if (share > _worst) _worst = share;
            if (largest > _largest) _largest = largest;
            if (share > MaxMismatch)
            {
                var hint = offOther <= MaxMismatch * covered ? " It matches the EXR " + Describe(other) + " instead." : " It matches neither encoding: channels in another order, or another view's values?";
                Fail(CheckFigures.Percent(share) + " of the covered pixels of the PNG differ from the EXR " + Describe(encoding) + " by more than " + ToleranceCodes +
                     " code (up to " + largest + ")." + hint);
            }
        }

        void CheckCoverage(CheckView view, string file, DatasetFile coverage, CheckImages images, List<DatasetProblem> problems)
        {
            PngImage png;
            try
            {
                if (!coverage.Exists) throw new FileNotFoundException(MaterialKeys.CoveragePath + " names " + coverage.Written + ", which is not a file inside the dataset.");
                png = PngReader.Read(coverage.FullPath);
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, MaterialKeys.CoveragePath + ": " + e.Message));
                _bad++;
                return;
            }
            if (png.BitDepth != 8 || png.Channels != 1 || png.Width != images.Width || png.Height != images.Height)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, MaterialKeys.CoveragePath + " is a " + png.Width + "×" + png.Height + " " + png.BitDepth + "-bit PNG with " +
                    png.Channels + " channel(s); it is an 8-bit grey image of the colour image's size."));
                _bad++;
                return;
            }
            if (images.Mask == null) return;
            int outside = 0, supported = 0;
            for (var i = 0; i < images.Mask.Length; i++)
            {
                if (png.Samples[i] == 0) continue;
                supported++;
                if (images.Mask[i] == 0) outside++;
            }
            // A lens resamples the supported flags to the nearest sample and the mask by its interpolated edge: a few edge pixels differ.
            if (outside > MaxCoverageMismatch * supported)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, MaterialKeys.CoveragePath + " marks " + outside + " pixel(s) supported where the mask is 0 (at most " +
                    CheckFigures.Percent(MaxCoverageMismatch) + " of the supported ones): a shader is read exactly only where the target is drawn."));
                _bad++;
            }
        }

        /// <summary>The PNG encoding dataset_config.json records for the pass, else the pass's own; null (and a problem) for an encoding this check does not know.</summary>
        MaterialPngEncoding? Encoding(MaterialPass pass, CheckView view, List<DatasetProblem> problems)
        {
            if (pass.Png == null) return MaterialPngEncoding.None;
            var recorded = MaterialRecord.PngEncoding(_config, pass.Name);
            if (recorded == null) return pass.Encoding;
            if (recorded == "srgb") return MaterialPngEncoding.Srgb;
            if (recorded == "linear") return MaterialPngEncoding.Linear;
            problems.Add(new DatasetProblem(Name, DatasetConfig.FileName, view.Frame, MaterialRecord.Key + ".encodings." + pass.Name + "_png is \"" + recorded +
                "\", not \"srgb\" or \"linear\"; the PNG cannot be compared with its EXR."));
            _bad++;
            return null;
        }

        ExrImage ReadExr(DatasetFile exr, MaterialPass pass, CheckView view, int width, int height, List<DatasetProblem> problems)
        {
            var file = "./" + view.ColourFile;
            if (exr == null || !exr.Exists)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, pass.Key + ": the EXR " + (exr?.Written ?? "(the key's path with .exr)") + " is not a file inside the dataset; every pass has its float EXR."));
                _bad++;
                return null;
            }
            try
            {
                var image = ExrReader.Read(exr.FullPath);
                if (image.Channel("R") != null && image.Channel("G") != null && image.Channel("B") != null && image.Channel("A") != null && image.Width == width && image.Height == height)
                    return image;
                problems.Add(new DatasetProblem(Name, file, view.Frame, exr.Written + " is " + image.Width + "×" + image.Height + " with channels " + string.Join("", image.Channels.Keys) +
                    "; a material EXR is R G B A floats of the colour image's size."));
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, exr.Written + " cannot be decoded: " + e.Message));
            }
            _bad++;
            return null;
        }

        PngImage ReadPng(DatasetFile png, MaterialPass pass, CheckView view, int width, int height, List<DatasetProblem> problems)
        {
            var file = "./" + view.ColourFile;
            if (!png.Exists)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, pass.Key + " names " + png.Written + ", which is not a file inside the dataset."));
                _bad++;
                return null;
            }
            try
            {
                var image = PngReader.Read(png.FullPath);
                if (image.BitDepth == 8 && image.Channels == 4 && image.Width == width && image.Height == height) return image;
                problems.Add(new DatasetProblem(Name, file, view.Frame, png.Written + " is a " + image.Width + "×" + image.Height + " " + image.BitDepth + "-bit PNG with " + image.Channels +
                    " channel(s); a material PNG is 8-bit RGBA of the colour image's size."));
            }
            catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, png.Written + " cannot be decoded: " + e.Message));
            }
            _bad++;
            return null;
        }

        static int AlphaByte(float a) => a > 0 ? (int)Math.Floor(Math.Min(1f, a) * 255.0 + 0.5) : 0;

        static int Encode(float value, MaterialPngEncoding encoding) =>
            encoding == MaterialPngEncoding.Srgb ? Srgb.EncodeByteExact(value) : MaterialEncoding.LinearByte(value);

        static string Describe(MaterialPngEncoding encoding) => encoding == MaterialPngEncoding.Srgb ? "sRGB-encoded" : "linearly encoded (no curve)";

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no frame names " + MaterialKeys.AlbedoPath + " or another material pass: materials are off");
            var figure = _files + " material files in " + _views + " views compared with their EXRs; worst " + CheckFigures.Percent(_worst) + " of covered pixels beyond " +
                         ToleranceCodes + " code (largest difference " + _largest + ")";
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure,
                "alpha = the colour image's; metallic/roughness grey in [0, 1]; PNG = EXR in its recorded encoding within " + ToleranceCodes + " code on ≥ " +
                CheckFigures.Percent(1 - MaxMismatch) + " of covered pixels", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
