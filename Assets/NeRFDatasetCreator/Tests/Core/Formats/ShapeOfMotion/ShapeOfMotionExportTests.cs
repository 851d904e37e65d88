using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --to shape-of-motion</c> from an analytic monocular capture with flow/ (10 steps, tracks from every
    /// frame), read back as Shape of Motion's iPhone reader reads it (vye16/shape-of-motion 697d462,
    /// flow3d/data/iphone_dataset.py and flow3d/data/utils.py, line by line below) and compared with our tracks npz.
    /// </summary>
    [TestFixture]
    public class ShapeOfMotionExportTests
    {
        TempFolder _temp;
        string _dataset, _export;
        ConversionResult _result;

        const int Frames = 10, Stride = 4;

        static AnalyticDataset.Options Options(int steps) => new AnalyticDataset.Options
        {
            Width = 64, Height = 48, Supersampling = 1, Train = steps, Val = 1, Test = 1,
            TimeSteps = steps, Monocular = true, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            Configure = s => { foreach (var split in new[] { s.Train, s.Val, s.Test }) split.Depth = ExtraOutput.PngAndExr; },
        };

        [OneTimeSetUp]
        public void Export()
        {
            _temp = new TempFolder();
            _dataset = AnalyticDataset.Write(_temp.Path, "mono", Options(Frames));
            FlowWriter.Write(_dataset, new FlowSettings { On = true, TrackQueryFrames = Enumerable.Range(0, Frames).ToArray(), TrackStride = Stride });
            _export = _temp.Combine("som");
            _result = DatasetConverter.Convert(_dataset, ExportTarget.ShapeOfMotion, _export);
        }

        [OneTimeTearDown]
        public void Clean() => _temp.Dispose();

        // iphone_dataset.py:96–103: frame_names and time_ids of splits/<split>.json.
        JObject Split(string split) => JObject.Parse(File.ReadAllText(Path.Combine(_export, "splits", split + ".json")));

        // iphone_dataset.py:252–259, 636–651: np.load(f"flow3d_preprocessed/2d_tracks/{factor}x/{query}_{target}.npy").astype(np.float32)
        NpyReader.NpyArray Tracks(string query, string target) =>
            NpyReader.Decode(File.ReadAllBytes(Path.Combine(_export, "flow3d_preprocessed", "2d_tracks", "1x", query + "_" + target + ".npy")), query + "_" + target);

        // utils.py:53–66, parse_tapir_track_info, in float32 as torch computes it.
        static (bool visible, bool invisible, float confidence) Parse(float occlusion, float expectedDist)
        {
            float Sigmoid(float x) => (float)(1.0f / (1.0f + (float)Math.Exp(-x)));
            var visibility = 1 - Sigmoid(occlusion);
            var confidence = 1 - Sigmoid(expectedDist);
            var validVisible = visibility * confidence > 0.5f;
            var validInvisible = (1 - visibility) * confidence > 0.5f;
            return (validVisible, validInvisible, confidence * (validVisible || validInvisible ? 1f : 0f));
        }

        [Test]
        public void TheTrainSplitIsTheQueryFramesWithTimeIdsZeroToNAndValIsEmpty()
        {
            var train = Split("train");
            Assert.That(train["frame_names"].Select(t => (string)t), Is.EqualTo(Enumerable.Range(0, Frames).Select(i => "0_" + i.ToString("D5"))));
            // iphone_dataset.py:653–658 indexes w2cs by time id: they must be the frame positions.
            Assert.That(train["time_ids"].Select(t => (int)t), Is.EqualTo(Enumerable.Range(0, Frames)));
            Assert.That(Split("val")["frame_names"], Is.Empty, "iphone_dataset.py:91–93: no validation set");
            Assert.That(_result.TrainCommands.Single(), Does.Contain("data:iphone --data.data-dir " + _export + " --data.depth-type lidar --data.camera-type original"));
        }

        [Test]
        public void EveryOrderedPairHasATrackFileAndTheReaderSeesOurTracksExactly()
        {
            var record = FlowRecord.Read(_dataset);
            var names = Split("train")["frame_names"].Select(t => (string)t).ToList();
            Assert.That(Directory.GetFiles(Path.Combine(_export, "flow3d_preprocessed", "2d_tracks", "1x")).Length, Is.EqualTo(Frames * Frames), "n² files");
            int visible = 0, occluded = 0, outside = 0;
            for (var a = 0; a < Frames; a++)
            {
                var ours = FlowTracksFile.Read(Path.Combine(_dataset, record.Tracks.Single(t => t.QueryFrame == a).File));
                Assert.That(ours.Points, Is.GreaterThan(20));
                // iphone_dataset.py:250–261: the query file {f}_{f}.npy; trainer.py:369–370 casts its (x, y) to int64 pixel indices.
                var query = Tracks(names[a], names[a]);
                Assert.That(query.Shape, Is.EqualTo(new[] { ours.Points, 4 }));
                for (var p = 0; p < ours.Points; p++)
                {
                    float x = query.Values[4 * p], y = query.Values[4 * p + 1];
                    Assert.That(x, Is.EqualTo(Math.Round(x)).And.EqualTo(ours.QueryXy[2 * p] - 0.5f), "query x is a whole pixel index");
                    Assert.That(y, Is.EqualTo(Math.Round(y)).And.EqualTo(ours.QueryXy[2 * p + 1] - 0.5f));
                    Assert.That((int)x % Stride, Is.EqualTo(0), "on the stride grid");
                }
                // Raster order of the query grid (trainer.py:365–377 pairs tracks with a row-major mask of the query pixels).
                var keys = Enumerable.Range(0, ours.Points).Select(p => query.Values[4 * p + 1] * 1000 + query.Values[4 * p]).ToList();
                Assert.That(keys, Is.Ordered.Ascending);
                for (var b = 0; b < Frames; b++)
                {
                    var target = Tracks(names[a], names[b]);
                    Assert.That(target.Shape, Is.EqualTo(new[] { ours.Points, 4 }));
                    for (var p = 0; p < ours.Points; p++)
                    {
                        var row = target.Values.Skip(4 * p).Take(4).ToArray();
                        Assert.That(row.All(v => !float.IsNaN(v)), Is.True, "no NaN reaches the reader");
                        var (isVisible, isInvisible, confidence) = Parse(row[2], row[3]);
                        Assert.That(confidence, Is.EqualTo(1f), "exact truth: the sigmoid saturates");
                        var state = a == b ? FlowState.Visible : ours.StateAt(b, p);
                        Assert.That(isVisible, Is.EqualTo(state == FlowState.Visible), names[a] + "→" + names[b] + " point " + p);
                        Assert.That(isInvisible, Is.EqualTo(state != FlowState.Visible));
                        if (a == b) continue;
                        if (float.IsNaN(ours.X(b, p))) Assert.That((row[0], row[1]), Is.EqualTo((-1f, -1f)));
                        else
                        {
                            // normalize_coords + align_corners=True (utils.py:27–29): pixel i's centre is i.
                            Assert.That(row[0] + 0.5, Is.EqualTo(ours.X(b, p)).Within(1e-5));
                            Assert.That(row[1] + 0.5, Is.EqualTo(ours.Y(b, p)).Within(1e-5));
                        }
                        if (state == FlowState.Visible) visible++;
                        else if (state == FlowState.Hidden) occluded++;
                        else outside++;
                    }
                }
            }
            Assert.That(visible, Is.GreaterThan(1000));
            Assert.That(occluded + outside, Is.GreaterThan(0), "the moving sphere hides some points");
        }

        [Test]
        public void QueryPointsLieInTheForegroundMaskAndTheMaskIsTheTargetsPixels()
        {
            var names = Split("train")["frame_names"].Select(t => (string)t).ToList();
            for (var a = 0; a < Frames; a++)
            {
                // iphone_dataset.py:168–188: track_anything/{factor}x/{frame}.png / 255.
                var mask = PngReader.Read(Path.Combine(_export, "flow3d_preprocessed", "track_anything", "1x", names[a] + ".png"));
                Assert.That((mask.Width, mask.Height), Is.EqualTo((64, 48)));
                var query = Tracks(names[a], names[a]);
                for (var p = 0; p < query.Shape[0]; p++)
                    Assert.That(mask.Samples[(int)query.Values[4 * p + 1] * 64 + (int)query.Values[4 * p]], Is.EqualTo(255), "get_tracks_3d keeps query points inside the mask (iphone_dataset.py:485–494)");
                // Independently: the target's pixels are where the dataset's depth EXR sees the analytic scene.
                var depth = ExrReader.Read(Path.Combine(_dataset, "train", "r_" + a + "_depth_0000.exr"));
                var y = depth.Channel("Y");
                var agree = 0;
                for (var v = 0; v < 48; v++)
                    for (var u = 0; u < 64; u++)
                        if ((mask.Samples[v * 64 + u] == 255) == (y[v * 64 + u] > 0 && y[v * 64 + u] < 1e9)) agree++;
                Assert.That(agree, Is.GreaterThan(64 * 48 * 95 / 100), "frame " + a);
            }
        }

        [Test]
        public void KeypointsAreTheFirstFramesTracksAtHalfSizeAsTheReaderScalesThem()
        {
            var record = FlowRecord.Read(_dataset);
            var ours = FlowTracksFile.Read(Path.Combine(_dataset, record.Tracks.Single(t => t.QueryFrame == 0).File));
            // iphone_dataset.py:697–716: sorted(glob("keypoint/2x/train/0_*.json")), time id from the name, × 2.0 / factor.
            var paths = Directory.GetFiles(Path.Combine(_export, "keypoint", "2x", "train"), "0_*.json").OrderBy(p => p, StringComparer.Ordinal).ToList();
            var timeIds = paths.Select(p => int.Parse(Path.GetFileNameWithoutExtension(p).Split('_')[1].Split('.')[0])).ToList();
            Assert.That(timeIds, Is.EqualTo(new[] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 }), "np.linspace(0, 10, 10, endpoint=False)");
            for (var i = 0; i < paths.Count; i++)
            {
                var rows = JArray.Parse(File.ReadAllText(paths[i]));
                Assert.That(rows.Count, Is.EqualTo(ours.Points));
                for (var p = 0; p < ours.Points; p++)
                {
                    float x = (float)rows[p][0] * 2f, y = (float)rows[p][1] * 2f, v = (float)rows[p][2];
                    if (ours.StateAt(timeIds[i], p) != FlowState.Visible)
                    {
                        Assert.That((x, y, v), Is.EqualTo((0f, 0f, 0f)));
                        continue;
                    }
                    Assert.That(v, Is.EqualTo(1f));
                    Assert.That(x + 0.5, Is.EqualTo(ours.X(timeIds[i], p)).Within(1e-4));
                    Assert.That(y + 0.5, Is.EqualTo(ours.Y(timeIds[i], p)).Within(1e-4));
                }
            }
        }

        [Test]
        public void DepthAndCamerasAreTheDyCheckFilesTheLidarAndOriginalOptionsRead()
        {
            // iphone_dataset.py:192–198 (depth-type lidar): np.load(depth/{factor}x/{frame}.npy)[..., 0];
            // 114–136 (camera-type original): camera/{frame}.json focal_length, principal_point, orientation, position.
            var depth = NpyReader.Decode(File.ReadAllBytes(Path.Combine(_export, "depth", "1x", "0_00003.npy")), "depth");
            Assert.That(depth.Shape, Is.EqualTo(new[] { 48, 64, 1 }));
            var camera = JObject.Parse(File.ReadAllText(Path.Combine(_export, "camera", "0_00003.json")));
            Assert.That(camera["focal_length"], Is.Not.Null);
            Assert.That(((JArray)camera["orientation"]).Count, Is.EqualTo(3));
            var rgba = PngReader.Read(Path.Combine(_export, "rgb", "1x", "0_00003.png"));
            Assert.That(rgba.Channels, Is.EqualTo(4), "imgs[..., 3] is the valid mask (iphone_dataset.py:165–166)");
        }

        [Test]
        public void ADatasetWithoutFlowOrTracksOrWithTooFewQueryFramesIsRefusedNamingTheFix()
        {
            using (var temp = new TempFolder())
            {
                var plain = AnalyticDataset.Write(temp.Path, "plain", Options(Frames));
                var e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(plain, ExportTarget.ShapeOfMotion, temp.Combine("a")));
                Assert.That(e.Problems.Single().Field, Is.EqualTo("flow"));
                Assert.That(e.Problems.Single().Fix, Does.Contain("nerf-dataset flow"));

                FlowWriter.Write(plain, new FlowSettings { On = true, TrackQueryFrames = new int[0] });
                e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(plain, ExportTarget.ShapeOfMotion, temp.Combine("b")));
                Assert.That(e.Problems.Single().Field, Is.EqualTo("flow.tracks"));
                Assert.That(e.Problems.Single().Value, Is.EqualTo("train"));

                var few = AnalyticDataset.Write(temp.Path, "few", Options(Frames));
                FlowWriter.Write(few, new FlowSettings { On = true, TrackQueryFrames = new[] { 0, 2, 4 }, TrackStride = 8 });
                e = Assert.Throws<InvalidParameterException>(() => DatasetConverter.Convert(few, ExportTarget.ShapeOfMotion, temp.Combine("c")));
                Assert.That(e.Problems.Single().Value, Is.EqualTo("3 query frames"));
                Assert.That(Directory.Exists(temp.Combine("c")), Is.False, "nothing written");
            }
        }
    }
}
