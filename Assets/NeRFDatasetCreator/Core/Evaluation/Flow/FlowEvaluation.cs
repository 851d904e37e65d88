using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset evaluate &lt;dataset&gt; --flow &lt;folder&gt;</c>: a model's rendered optical flow and tracks
    /// (<see cref="FlowPredictions"/>) scored against the dataset's exact <c>flow/</c> (issue 37) — EPE on the pixels
    /// visible in both frames and on all pixels with a surface, PCK-T of the tracks (<see cref="FlowMetrics"/>). Every file
    /// is read and checked before anything is written; then <c>metrics.json</c> goes into the out folder under
    /// <see cref="EvaluationOutput"/>'s rule.
    /// </summary>
    public static class FlowEvaluation
    {
        public const string FileName = MetricsJson.FileName;

        public static FlowEvaluationResult Run(string datasetFolder, string predictionFolder, string outFolder = null)
        {
            var root = Path.GetFullPath(datasetFolder);
            FlowRecord record;
            try { record = FlowRecord.Read(root); }
            catch (InvalidDataException e) { throw Refuse("flow", FlowLayout.RecordFile, "cannot be read: " + e.Message, "Compute the dataset's flow again (nerf-dataset flow <dataset> into a copy without flow/)."); }
            if (record == null)
                throw Refuse("flow", Path.Combine(root, FlowLayout.RecordFile), "does not exist: the dataset has no motion ground truth to score against.",
                    "Compute it: nerf-dataset flow <dataset>, or capture with the \"flow\" settings section (Documentation~/output-format.md, flow/).");
            var folder = Path.GetFullPath(predictionFolder);
            if (!Directory.Exists(folder)) throw Refuse("--flow", folder, "is not an existing folder.", "Pass the folder holding <video>/flow_<a>_<b>.flo and <video>/tracks_<q>.npz (Documentation~/evaluate.md, Motion).");

            var result = new FlowEvaluationResult { Dataset = root, Predictions = folder, OutFolder = Path.GetFullPath(outFolder ?? Path.Combine(folder, "evaluation-flow")) };
            var flowFiles = record.Pairs.Select(p => FlowPredictions.Full(folder, p.FlowFile)).ToList();
            var trackFiles = record.Tracks.Select(t => FlowPredictions.Full(folder, t.File)).ToList();
            var hasFlow = Complete("flow", flowFiles, record.Pairs.Select(p => FlowPredictions.Relative(p.FlowFile)).ToList());
            var hasTracks = Complete("tracks", trackFiles, record.Tracks.Select(t => FlowPredictions.Relative(t.File)).ToList());
            if (!hasFlow && !hasTracks)
                throw Refuse("--flow", folder, "holds neither flow nor tracks for this dataset: " + string.Join(", ", flowFiles.Concat(trackFiles).Take(2)) + (flowFiles.Count + trackFiles.Count > 2 ? " …" : "") + " are missing.",
                    "Render the model's flow as <video>/flow_<a>_<b>.flo for every pair of " + FlowLayout.RecordFile + " and/or its tracks as <video>/tracks_<q>.npz (xy), Documentation~/evaluate.md.");
            if (hasFlow)
                for (var i = 0; i < record.Pairs.Count; i++) result.Pairs.Add(ScorePair(root, record.Pairs[i], flowFiles[i]));
            if (hasTracks)
                for (var i = 0; i < record.Tracks.Count; i++) result.Tracks.Add(ScoreTracks(root, record.Tracks[i], trackFiles[i], ImageSize(root, record)));

            var created = !Directory.Exists(result.OutFolder);
            EvaluationOutput.Prepare(result.OutFolder, root);
            try
            {
                AtomicFile.WriteNewText(Path.Combine(result.OutFolder, FileName), MetricsJson.Text(Json(result)));
                EvaluationOutput.Finish(result.OutFolder);
                // Prepare makes an errors/ folder for image evaluations; flow has no error maps.
                var errors = Path.Combine(result.OutFolder, EvaluationOutput.ErrorFolder);
                if (Directory.Exists(errors) && Directory.GetFileSystemEntries(errors).Length == 0) FileOps.DeleteDirectory(errors);
            }
            catch
            {
                EvaluationOutput.RemoveWritten(result.OutFolder, created);
                throw;
            }
            return result;
        }

        /// <summary>True when every file is there, false when none is; some but not all is refused naming the missing ones (a subset would score another mean).</summary>
        static bool Complete(string what, IReadOnlyList<string> full, IReadOnlyList<string> relative)
        {
            var missing = Enumerable.Range(0, full.Count).Where(i => !File.Exists(full[i])).ToList();
            if (missing.Count == full.Count) return false;
            if (missing.Count == 0) return true;
            throw Refuse("--flow", full[missing[0]], "is missing: the folder holds " + what + " for " + (full.Count - missing.Count) + " of the " + full.Count + " files the dataset has" +
                (missing.Count > 1 ? " (also missing: " + string.Join(", ", missing.Skip(1).Take(3).Select(i => relative[i])) + (missing.Count > 4 ? " and " + (missing.Count - 4) + " more" : "") + ")" : "") + ".",
                "Render " + what + " for every one, or for none: a subset would give another mean.");
        }

        static FlowPairScore ScorePair(string root, FlowPair pair, string predictedPath)
        {
            var truth = FloFile.Read(Path.Combine(root, pair.FlowFile.Replace('/', Path.DirectorySeparatorChar)), out var w, out var h);
            var occluded = Mask(root, pair.OccludedFile, w, h);
            var outside = Mask(root, pair.OutsideFile, w, h);
            float[] predicted;
            try { predicted = FloFile.Read(predictedPath, out var pw, out var ph); if (pw != w || ph != h) throw Refuse("--flow", predictedPath, "is " + pw + " × " + ph + " pixels; the dataset's frames are " + w + " × " + h + ".", "Render the flow at the dataset's resolution."); }
            catch (InvalidDataException e) { throw Refuse("--flow", predictedPath, "cannot be read: " + e.Message, "Write Middlebury .flo (tag PIEH, width, height, float32 dx dy per pixel)."); }
            bool Surface(int p) => !float.IsNaN(truth[2 * p]) && !float.IsNaN(truth[2 * p + 1]);
            var notFinite = 0;
            for (var p = 0; p < w * h; p++)
                if (Surface(p) && !(IsFinite(predicted[2 * p]) && IsFinite(predicted[2 * p + 1]))) notFinite++;
            if (notFinite > 0)
                throw Refuse("--flow", predictedPath, "has no finite flow at " + notFinite + " pixels where the dataset's frame has a surface.", "Render a finite flow for every pixel of the target.");
            var visible = FlowMetrics.Epe(truth, predicted, p => Surface(p) && occluded[p] == 0 && outside[p] == 0, out var visiblePixels);
            var all = FlowMetrics.Epe(truth, predicted, Surface, out var allPixels);
            return new FlowPairScore(pair, FlowPredictions.Relative(pair.FlowFile), visible, visiblePixels, all, allPixels);
        }

        static FlowTracksScore ScoreTracks(string root, FlowRecordTracks tracks, string predictedPath, (int w, int h) size)
        {
            var ours = Path.Combine(root, tracks.File.Replace('/', Path.DirectorySeparatorChar));
            var truth = FlowPredictions.NpzArray(ours, "xy");
            var state = FlowPredictions.NpzArray(ours, "state");
            if (truth.Shape.Length != 3 || truth.Shape[2] != 2 || !FlowPredictions.Shaped(state, truth.Shape[0], truth.Shape[1]))
                throw new InvalidDataException(ours + ": xy " + FlowPredictions.ShapeText(truth.Shape) + " and state " + FlowPredictions.ShapeText(state.Shape) + " are not (T, N, 2) and (T, N).");
            int frames = truth.Shape[0], points = truth.Shape[1];
            NpyReader.NpyArray predicted;
            try { predicted = FlowPredictions.NpzArray(predictedPath, "xy"); }
            catch (InvalidDataException e) { throw Refuse("--flow", predictedPath, "cannot be read: " + e.Message, "Write np.savez(path, xy=<(T, N, 2) float array>)."); }
            if (!FlowPredictions.Shaped(predicted, frames, points, 2))
                throw Refuse("--flow", predictedPath, "holds xy of shape " + FlowPredictions.ShapeText(predicted.Shape) + ", not the " + FlowPredictions.ShapeText(new[] { frames, points, 2 }) + " of the dataset's " + tracks.File + ".",
                    "Track the dataset's query points (its query_xy, in order) through every frame of the video.");
            var threshold = FlowMetrics.PckThreshold(size.w, size.h);
            var pairs = FlowMetrics.PckT(truth.Values, state.Values.Select(v => (byte)v).ToArray(), predicted.Values, frames, points, tracks.QueryFrame, threshold);
            return new FlowTracksScore(tracks, FlowPredictions.Relative(tracks.File), threshold, pairs);
        }

        /// <summary>The frames' size: the first pair's flow file's, else the first frame's image.</summary>
        static (int, int) ImageSize(string root, FlowRecord record)
        {
            if (record.Pairs.Count > 0)
            {
                FloFile.Read(Path.Combine(root, record.Pairs[0].FlowFile.Replace('/', Path.DirectorySeparatorChar)), out var w, out var h);
                return (w, h);
            }
            var image = PngReader.Read(Path.Combine(root, record.Videos[0].Frames[0].Image.Replace('/', Path.DirectorySeparatorChar)));
            return (image.Width, image.Height);
        }

        static byte[] Mask(string root, string relative, int w, int h)
        {
            var png = PngReader.Read(Path.Combine(root, relative.Replace('/', Path.DirectorySeparatorChar)));
            if (png.Width != w || png.Height != h || png.Channels != 1 || png.BitDepth != 8) throw new InvalidDataException(relative + " is not an 8-bit grey mask of " + w + " × " + h + " pixels (nerf-dataset check names what is wrong with flow/).");
            return png.Samples;
        }

        static bool IsFinite(float v) => !float.IsNaN(v) && !float.IsInfinity(v);

        public static JObject Json(FlowEvaluationResult r) => new JObject
        {
            ["generator"] = MetricsJson.Generator,
            ["kind"] = "flow",
            ["dataset"] = r.Dataset,
            ["predictions"] = r.Predictions,
            ["definitions"] = new JObject
            {
                ["epe_visible"] = "end-point error ||F_pred - F_true||_2 in pixels over the pixels of frame a visible in frame b (finite flow, occluded and outside masks 0), mean per pair, then mean over pairs (Shape of Motion's aggregation)",
                ["epe_all"] = "the same over every pixel with a surface (finite true flow: visible, occluded, or projecting outside frame b)",
                ["pck_t"] = "per pair (query frame q, frame t != q), the share of the query points visible at both whose predicted position is strictly nearer than ratio * max(W, H) to the truth, then mean over pairs with such points (DyCheck compute_pck, kp_transfer)",
                ["pck_ratio"] = FlowMetrics.PckRatio,
            },
            ["flow"] = r.Pairs.Count == 0 ? JValue.CreateNull() : (JToken)new JObject
            {
                ["pairs"] = r.Pairs.Count,
                ["epe_visible"] = MetricsJson.Num(r.EpeVisible),
                ["epe_all"] = MetricsJson.Num(r.EpeAll),
                ["per_pair"] = new JArray(r.Pairs.Select(p => new JObject
                {
                    ["video"] = p.Pair.Video, ["from"] = p.Pair.From, ["to"] = p.Pair.To, ["file"] = p.File,
                    ["epe_visible"] = MetricsJson.Num(p.EpeVisible), ["pixels_visible"] = p.VisiblePixels,
                    ["epe_all"] = MetricsJson.Num(p.EpeAll), ["pixels_all"] = p.AllPixels,
                })),
            },
            ["tracks"] = r.Tracks.Count == 0 ? JValue.CreateNull() : (JToken)new JObject
            {
                ["files"] = r.Tracks.Count,
                ["pck_t"] = MetricsJson.Num(r.PckT),
                ["threshold_px"] = r.Tracks[0].Threshold,
                ["pairs"] = r.Tracks.Sum(t => t.Pairs.Count),
                ["per_file"] = new JArray(r.Tracks.Select(t => new JObject
                {
                    ["video"] = t.Tracks.Video, ["query_frame"] = t.Tracks.QueryFrame, ["file"] = t.File,
                    ["pck_t"] = MetricsJson.Num(FlowMetrics.MeanOverPairs(t.Pairs.Select(p => p.Pck))), ["pairs"] = t.Pairs.Count,
                })),
            },
        };

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }

    public sealed class FlowPairScore
    {
        public FlowPairScore(FlowPair pair, string file, double epeVisible, int visiblePixels, double epeAll, int allPixels)
        {
            Pair = pair;
            File = file;
            EpeVisible = epeVisible;
            VisiblePixels = visiblePixels;
            EpeAll = epeAll;
            AllPixels = allPixels;
        }

        public FlowPair Pair { get; }
        public string File { get; }
        public double EpeVisible { get; }
        public int VisiblePixels { get; }
        public double EpeAll { get; }
        public int AllPixels { get; }
    }

    public sealed class FlowTracksScore
    {
        public FlowTracksScore(FlowRecordTracks tracks, string file, double threshold, IReadOnlyList<PckPair> pairs)
        {
            Tracks = tracks;
            File = file;
            Threshold = threshold;
            Pairs = pairs;
        }

        public FlowRecordTracks Tracks { get; }
        public string File { get; }
        public double Threshold { get; }
        public IReadOnlyList<PckPair> Pairs { get; }
    }

    /// <summary>What <see cref="FlowEvaluation.Run"/> scored: per pair and per tracks file, and the means over pairs.</summary>
    public sealed class FlowEvaluationResult
    {
        public string Dataset, Predictions, OutFolder;
        public readonly List<FlowPairScore> Pairs = new List<FlowPairScore>();
        public readonly List<FlowTracksScore> Tracks = new List<FlowTracksScore>();

        public double EpeVisible => FlowMetrics.MeanOverPairs(Pairs.Select(p => p.EpeVisible));
        public double EpeAll => FlowMetrics.MeanOverPairs(Pairs.Select(p => p.EpeAll));

        /// <summary>The mean over every (query, frame) pair of every tracks file, as DyCheck averages over its pairs.</summary>
        public double PckT => FlowMetrics.MeanOverPairs(Tracks.SelectMany(t => t.Pairs).Select(p => p.Pck));
    }
}
