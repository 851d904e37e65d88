using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>relight</b>: a dataset with relighting (dataset_config.json's <c>relighting</c> record, or frames with
    /// <c>relit_paths</c>) names, for every view, an image per recorded key, each existing, of the view's size, 8-bit RGBA,
    /// with the alpha of the view's own image within <see cref="ToleranceCodes"/> code (the same geometry; the matting
    /// pair of another light rounds differently by at most that); <c>lights/lights.json</c> parses as this plugin's lights
    /// file, its keys are the record's, and each environment's EXR exists, decodes and is twice as wide as high.
    /// </summary>
    public sealed class RelightCheck : IViewCheck
    {
        /// <summary>A relit alpha may differ from the view's by this many codes (half-float rounding of another light's matting pair).</summary>
        public const int ToleranceCodes = 1;

        public string Name => "relight";

        readonly string _root;
        readonly IReadOnlyList<string> _keys;
        readonly List<DatasetProblem> _datasetProblems = new List<DatasetProblem>();
        bool _datasetReported;
        int _views, _images, _bad, _largest;

        public RelightCheck(string root, DatasetConfig config)
        {
            _root = root;
            var record = config?.Relighting;
            _keys = record?.Keys;
            if (record != null) Lights(record);
        }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (!_datasetReported)
            {
                _datasetReported = true;
                problems.AddRange(_datasetProblems);
                _bad += _datasetProblems.Count;
            }
            var frame = view.Source;
            var relit = frame?.Relit ?? FrameRelit.None;
            if (_keys == null && !relit.Recorded) return;
            var file = "./" + view.FrameImageFile;
            _views++;
            if (relit.Problem != null)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, relit.Problem));
                _bad++;
            }
            if (_keys == null)
            {
                problems.Add(new DatasetProblem(Name, file, view.Frame, RelightingKeys.RelitPaths + " is written, but " + DatasetLayout.ConfigFileName +
                    " has no relighting record listing the keys: the dataset was edited, or its config belongs to another capture."));
                _bad++;
                return;
            }
            foreach (var pair in relit.Paths)
                if (!_keys.Contains(pair.Key))
                {
                    problems.Add(new DatasetProblem(Name, file, view.Frame, RelightingKeys.RelitPaths + " names \"" + pair.Key + "\", which the relighting record of " +
                        DatasetLayout.ConfigFileName + " does not list (" + string.Join(", ", _keys) + ")."));
                    _bad++;
                }
            foreach (var key in _keys)
            {
                var image = frame.RelitFile(key);
                if (image == null)
                {
                    problems.Add(new DatasetProblem(Name, file, view.Frame, RelightingKeys.RelitPaths + " has no \"" + key + "\"; every view has an image per recorded key."));
                    _bad++;
                    continue;
                }
                if (!image.Exists)
                {
                    problems.Add(new DatasetProblem(Name, file, view.Frame, RelightingKeys.RelitPaths + "." + key + " names " + image.Written + ", which is not a file inside the dataset."));
                    _bad++;
                    continue;
                }
                _images++;
                if (images.Alpha == null) continue;
                PngImage png;
                try
                {
                    png = PngReader.Read(image.FullPath);
                }
                catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
                {
                    problems.Add(new DatasetProblem(Name, file, view.Frame, image.Written + " cannot be decoded: " + e.Message));
                    _bad++;
                    continue;
                }
                if (png.Width != images.Width || png.Height != images.Height || png.BitDepth != 8 || png.Channels != 4)
                {
                    problems.Add(new DatasetProblem(Name, file, view.Frame, image.Written + " is " + png.Width + "×" + png.Height + " " + png.BitDepth + "-bit with " + png.Channels +
                        " channels; a relit image is 8-bit RGBA of the view's size (" + images.Width + "×" + images.Height + ")."));
                    _bad++;
                    continue;
                }
                int largest = 0, differing = 0;
                var samples = png.Samples;
                for (int i = 0, n = images.Width * images.Height; i < n; i++)
                {
                    var difference = Math.Abs(samples[i * 4 + 3] - images.Alpha[i]);
                    if (difference > ToleranceCodes) differing++;
                    if (difference > largest) largest = difference;
                }
                if (largest > _largest) _largest = largest;
                if (differing > 0)
                {
                    problems.Add(new DatasetProblem(Name, file, view.Frame, image.Written + "'s alpha differs from the view's image by more than " + ToleranceCodes +
                        " code on " + differing + " pixel(s) (up to " + largest + "): a relit image shows the same geometry, so it has the view's alpha (another view's image, or its alpha lost?)."));
                    _bad++;
                }
            }
        }

        /// <summary>lights/lights.json against the record: parses, its keys are the record's, each environment's EXR is 2:1.</summary>
        void Lights(RelightingRecord record)
        {
            var file = record.LightsFile ?? RelightingKeys.LightsFile;
            void Problem(string message) => _datasetProblems.Add(new DatasetProblem(Name, file, -1, message));
            var path = Path.Combine(_root, RelightingKeys.LightsFile);
            if (record.LightsFile != RelightingKeys.LightsFile)
                Problem(DatasetLayout.ConfigFileName + "'s relighting record names \"" + record.LightsFile + "\" as its lights file; this plugin writes " + RelightingKeys.LightsFile + ".");
            JObject lights;
            try
            {
                lights = JObject.Parse(File.ReadAllText(path));
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is Newtonsoft.Json.JsonException)
            {
                Problem("cannot be read as JSON (" + e.Message + "); the relighting record of " + DatasetLayout.ConfigFileName + " says it describes the lights.");
                return;
            }
            if ((string)lights["format"] != LightsFile.Format)
                Problem("has \"format\" " + (lights["format"]?.ToString(Newtonsoft.Json.Formatting.None) ?? "missing") + ", not \"" + LightsFile.Format + "\".");
            var keys = new List<string>();
            if (!(lights["conditions"] is JArray conditions))
            {
                Problem("has no \"conditions\" list.");
                return;
            }
            for (var i = 0; i < conditions.Count; i++)
            {
                var c = conditions[i] as JObject;
                var at = "conditions[" + i + "]";
                if (c == null)
                {
                    Problem(at + " is not an object.");
                    continue;
                }
                if (c["keys"] is JArray list) keys.AddRange(list.Where(k => k.Type == JTokenType.String).Select(k => (string)k));
                if ((string)c["kind"] != LightingKinds.Name(LightingKind.Environment)) continue;
                var exr = c["file"]?.Type == JTokenType.String ? (string)c["file"] : null;
                var resolved = exr == null ? null : DatasetFile.Resolve(_root, at + ".file", exr, false);
                if (resolved == null || !resolved.Exists)
                {
                    Problem(at + ".file " + (exr == null ? "is missing" : "names " + exr + ", which is not a file inside the dataset") + "; an environment's map is written as lights/<name>.exr.");
                    continue;
                }
                try
                {
                    var image = ExrReader.Read(resolved.FullPath);
                    if (image.Width != 2 * image.Height)
                        Problem(at + ".file " + exr + " is " + image.Width + "×" + image.Height + "; an equirect map is twice as wide as it is high.");
                    if (image.Channel("R") == null || image.Channel("G") == null || image.Channel("B") == null)
                        Problem(at + ".file " + exr + " has channels " + string.Join("", image.Channels.Keys) + "; an environment map is R G B floats.");
                }
                catch (Exception e) when (e is InvalidDataException || e is IOException || e is UnauthorizedAccessException)
                {
                    Problem(at + ".file " + exr + " cannot be decoded: " + e.Message);
                }
            }
            if (!keys.SequenceEqual(record.Keys))
                Problem("lists the keys " + string.Join(", ", keys) + ", but the relighting record of " + DatasetLayout.ConfigFileName + " lists " + string.Join(", ", record.Keys) +
                    ": the two were written together and must agree.");
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0 && _bad == 0) return DatasetCheckResult.Skip(Name, "no relighting record and no frame names " + RelightingKeys.RelitPaths + ": relighting is off");
            var figure = _images + " relit images of " + _views + " views; largest alpha difference from the view's image " + _largest + " code(s)";
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure,
                "an image per recorded key and view, its alpha within " + ToleranceCodes + " code of the view's; lights.json agrees with the record, its environment EXRs 2:1",
                _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
