using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>evaluate --flow</c> (<see cref="FlowEvaluation"/>) on an analytic dynamic dataset with flow/: a prediction equal to
    /// the truth scores EPE 0 and PCK-T 1; one moved by a known amount scores what that amount gives by hand; a
    /// prediction folder with a file missing, of another size or shape, or a dataset without flow is refused naming the file.
    /// </summary>
    public class FlowEvaluationTests
    {
        static string Dataset(TempFolder temp)
        {
            var folder = AnalyticDataset.Write(temp.Path, "mono", new AnalyticDataset.Options
            {
                Width = 64, Height = 48, Supersampling = 1, Train = 4, Val = 1, Test = 1, TimeSteps = 4, Monocular = true, PointCloud = 0,
                MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            });
            FlowWriter.Write(folder, new FlowSettings { On = true, TrackQueryFrames = new[] { 0, 2 }, TrackStride = 4 });
            return folder;
        }

        /// <summary>A prediction folder made from the dataset's own flow/, each flow moved by (ox, oy) and each track by (tx, ty).</summary>
        static string Predictions(TempFolder temp, string dataset, float ox, float oy, float tx, float ty)
        {
            var folder = temp.Combine("predictions-" + ox + "-" + oy + "-" + tx + "-" + ty);
            var record = FlowRecord.Read(dataset);
            foreach (var pair in record.Pairs)
            {
                var flow = FloFile.Read(Path.Combine(dataset, pair.FlowFile), out var w, out var h);
                for (var p = 0; p < w * h; p++)
                {
                    // A model renders flow everywhere: where ours is NaN (no surface) any value, here 0.
                    flow[2 * p] = float.IsNaN(flow[2 * p]) ? 0 : flow[2 * p] + ox;
                    flow[2 * p + 1] = float.IsNaN(flow[2 * p + 1]) ? 0 : flow[2 * p + 1] + oy;
                }
                var path = FlowPredictions.Full(folder, pair.FlowFile);
                Directory.CreateDirectory(Path.GetDirectoryName(path));
                File.WriteAllBytes(path, FloFile.Encode(flow, w, h));
            }
            foreach (var t in record.Tracks)
            {
                var xy = FlowPredictions.NpzArray(Path.Combine(dataset, t.File), "xy");
                var moved = xy.Values.Select((v, i) => v + (i % 2 == 0 ? tx : ty)).ToArray();
                var path = FlowPredictions.Full(folder, t.File);
                Directory.CreateDirectory(Path.GetDirectoryName(path));
                File.WriteAllBytes(path, NumpyFiles.Npz(new[] { new KeyValuePair<string, byte[]>("xy", NumpyFiles.Float32Array(moved, xy.Shape)) }));
            }
            return folder;
        }

        [Test]
        public void ThePerfectPredictionScoresEpeZeroAndPckOne()
        {
            using (var temp = new TempFolder())
            {
                var dataset = Dataset(temp);
                var result = FlowEvaluation.Run(dataset, Predictions(temp, dataset, 0, 0, 0, 0));
                Assert.That(result.Pairs.Count, Is.EqualTo(6), "3 forward and 3 backward pairs of 4 frames");
                Assert.That(result.EpeVisible, Is.EqualTo(0));
                Assert.That(result.EpeAll, Is.EqualTo(0));
                Assert.That(result.Pairs.All(p => p.VisiblePixels > 0 && p.AllPixels >= p.VisiblePixels), Is.True);
                Assert.That(result.Tracks.Count, Is.EqualTo(2));
                Assert.That(result.PckT, Is.EqualTo(1));
                var json = JObject.Parse(File.ReadAllText(Path.Combine(result.OutFolder, "metrics.json")));
                Assert.That((string)json["generator"], Is.EqualTo(MetricsJson.Generator));
                Assert.That((double)json["flow"]["epe_visible"], Is.EqualTo(0));
                Assert.That((double)json["tracks"]["pck_t"], Is.EqualTo(1));
                Assert.That((double)json["tracks"]["threshold_px"], Is.EqualTo(3.2).Within(1e-12), "0.05 × 64");
                Assert.That(Directory.GetFileSystemEntries(result.OutFolder).Select(Path.GetFileName), Is.EqualTo(new[] { "metrics.json" }));
            }
        }

        [Test]
        public void AKnownOffsetScoresWhatItGivesByHand()
        {
            using (var temp = new TempFolder())
            {
                var dataset = Dataset(temp);
                // Flow off by (3, 4): EPE exactly 5 on every scored pixel. Tracks off by 3.1 px in x: inside 3.2 px, every point correct.
                var near = FlowEvaluation.Run(dataset, Predictions(temp, dataset, 3, 4, 3.1f, 0));
                Assert.That(near.EpeVisible, Is.EqualTo(5).Within(1e-5));
                Assert.That(near.EpeAll, Is.EqualTo(5).Within(1e-5));
                Assert.That(near.PckT, Is.EqualTo(1));
                // Tracks off by (2, 2.6): |·| = 3.280 > 3.2, no point correct.
                var far = FlowEvaluation.Run(dataset, Predictions(temp, dataset, 0, 0, 2, 2.6f));
                Assert.That(far.PckT, Is.EqualTo(0));
            }
        }

        [Test]
        public void MissingOrWrongFilesAreRefusedNamingThem()
        {
            using (var temp = new TempFolder())
            {
                var dataset = Dataset(temp);
                var folder = Predictions(temp, dataset, 0, 0, 0, 0);
                var lost = Path.Combine(folder, "train", "flow_0001_0002.flo");
                File.Delete(lost);
                var e = Assert.Throws<InvalidParameterException>(() => FlowEvaluation.Run(dataset, folder));
                Assert.That(e.Message, Does.Contain(lost).And.Contain("is missing: the folder holds flow for 5 of the 6 files"));
                File.WriteAllBytes(lost, FloFile.Encode(new float[2 * 32 * 24], 32, 24));
                e = Assert.Throws<InvalidParameterException>(() => FlowEvaluation.Run(dataset, folder));
                Assert.That(e.Message, Does.Contain(lost).And.Contain("is 32 × 24 pixels; the dataset's frames are 64 × 48"));
                File.WriteAllBytes(lost, File.ReadAllBytes(Path.Combine(dataset, "flow", "train", "flow_0001_0002.flo"))); // NaN where there is no surface: fine
                var tracks = Path.Combine(folder, "train", "tracks_0002.npz");
                File.WriteAllBytes(tracks, NumpyFiles.Npz(new[] { new KeyValuePair<string, byte[]>("xy", NumpyFiles.Float32Array(new float[2 * 3], 1, 3, 2)) }));
                e = Assert.Throws<InvalidParameterException>(() => FlowEvaluation.Run(dataset, folder));
                Assert.That(e.Message, Does.Contain(tracks).And.Contain("holds xy of shape (1, 3, 2), not the (4, "));
                Assert.That(Directory.Exists(Path.Combine(folder, "evaluation-flow")), Is.False, "a refusal writes nothing");

                var empty = temp.Combine("empty");
                Directory.CreateDirectory(empty);
                e = Assert.Throws<InvalidParameterException>(() => FlowEvaluation.Run(dataset, empty));
                Assert.That(e.Message, Does.Contain("holds neither flow nor tracks").And.Contain(Path.Combine(empty, "train", "flow_0000_0001.flo")));

                var plain = AnalyticDataset.Write(temp.Path, "plain", new AnalyticDataset.Options { Width = 32, Height = 24, Train = 2, Val = 1, Test = 1 });
                e = Assert.Throws<InvalidParameterException>(() => FlowEvaluation.Run(plain, folder));
                Assert.That(e.Message, Does.Contain(Path.Combine(plain, "flow", "flow.json")).And.Contain("nerf-dataset flow"));
            }
        }
    }
}
