using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A capture whose settings have the "flow" section writes flow/ itself, after its geometry pack (the analytic
    /// capture runs the same <see cref="DatasetRun.Finish"/> as the Editor's), records it in dataset_config.json, and
    /// the dataset still passes check. Also: the thread count does not change a byte, and a topology change names the object.
    /// </summary>
    public class FlowCaptureTests
    {
        static AnalyticDataset.Options Options(bool monocular, bool flow) => new AnalyticDataset.Options
        {
            Width = 48, Height = 36, Supersampling = 1, Train = monocular ? 4 : 2, Val = 1, Test = 1,
            TimeSteps = monocular ? 4 : 3, Monocular = monocular, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            Configure = s =>
            {
                if (!flow) return;
                s.Flow.On = true;
                s.Flow.TrackQueryFrames = new[] { 0 };
                s.Flow.TrackStride = 6;
            },
        };

        [TestCase(true, 1, 6)]
        [TestCase(false, 4, 16)]
        public void TheCaptureWritesFlowRecordsItAndCheckPasses(bool monocular, int videos, int pairs)
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, monocular ? "mono" : "multi", Options(monocular, flow: true));
                var record = FlowRecord.Read(folder);
                Assert.That(record, Is.Not.Null, "flow/flow.json");
                // Monocular: the train video of 4 frames, 3 forward + 3 backward. Multi-view: train cam 0 and 1, val cam 0, test cam 0, 3 steps each, 2 + 2 pairs.
                Assert.That(record.Videos.Count, Is.EqualTo(videos));
                Assert.That(record.Pairs.Count, Is.EqualTo(pairs));
                Assert.That(record.Tracks.Count, Is.EqualTo(videos), "one tracks file per video for query frame 0");
                foreach (var p in record.Pairs)
                    Assert.That(File.Exists(Path.Combine(folder, p.FlowFile)), Is.True, p.FlowFile);
                var config = JObject.Parse(File.ReadAllText(Path.Combine(folder, "dataset_config.json")));
                Assert.That(config["flow"], Is.EqualTo(new JObject { ["record"] = "flow/flow.json", ["pairs"] = pairs, ["videos"] = videos, ["tracks"] = videos }));
                Assert.That(config["geometry"]?["steps"], Is.Not.Null, "the rest of the config is still written");
                Assert.That(config["settings"]?["flow"]?["tracks"]?["stride"]?.Value<int>(), Is.EqualTo(6));
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(8)));
                Assert.That(report.Failed, Is.False);
            }
        }

        [Test]
        public void ADatasetWithFlowIsStillProvablyOursAndAStrayFileInFlowIsNot()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "mono", Options(true, flow: true));
                Assert.That(OwnDataset.WhyNotOurs(folder), Is.Null, "every file under flow/ is one the plugin writes");
                Assert.That(OwnDataset.WhyNotReplaceable(folder, rendersImages: true), Is.Null, "a new capture may replace it");
                File.WriteAllText(Path.Combine(folder, "flow", "train", "notes.txt"), "mine");
                Assert.That(OwnDataset.WhyNotOurs(folder), Does.Contain("notes.txt"));
            }
            Assert.That(FlowLayout.IsVideoFile("flow_0000_0001.flo") && FlowLayout.IsVideoFile("scene_flow_0012_0010.exr") && FlowLayout.IsVideoFile("tracks_0000.npz"), Is.True);
            Assert.That(FlowLayout.IsVideoFile("flow_0_1.flo") || FlowLayout.IsVideoFile("flow_0000_0001.png"), Is.False);
        }

        [Test]
        public void WithoutTheSectionNoFlowIsWrittenAndTheConfigHasNoRecord()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "mono", Options(true, flow: false));
                Assert.That(Directory.Exists(Path.Combine(folder, "flow")), Is.False);
                Assert.That(JObject.Parse(File.ReadAllText(Path.Combine(folder, "dataset_config.json")))["flow"], Is.Null);
            }
        }

        [Test]
        public void TheSummarySentenceCountsPairsVideosAndTracks()
        {
            var json = new JObject { ["pairs"] = new JArray(1, 2, 3), ["videos"] = new JArray(1), ["tracks"] = new JArray() };
            Assert.That(FlowConfigRecord.Summary(json), Is.EqualTo("flow/ holds 3 frame pairs of 1 video and 0 tracks files (flow/flow.json)."));
        }

        [Test]
        public void OneAndTwoThreadsWriteTheSameBytes()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "multi", Options(false, flow: false));
                var one = DatasetFaults.Copy(folder, Path.Combine(temp.Path, "one"));
                var two = DatasetFaults.Copy(folder, Path.Combine(temp.Path, "two"));
                var settings = new FlowSettings { On = true, Spans = new[] { 1, 2 }, TrackQueryFrames = new[] { 0, 2 }, TrackStride = 3 };
                FlowWriter.Write(one, settings, threads: 1);
                FlowWriter.Write(two, settings, threads: 2);
                var files = Directory.GetFiles(Path.Combine(one, "flow"), "*", SearchOption.AllDirectories).Select(f => f.Substring(one.Length)).OrderBy(f => f).ToList();
                Assert.That(files.Count, Is.GreaterThan(20));
                Assert.That(Directory.GetFiles(Path.Combine(two, "flow"), "*", SearchOption.AllDirectories).Select(f => f.Substring(two.Length)).OrderBy(f => f), Is.EqualTo(files));
                foreach (var f in files)
                    Assert.That(File.ReadAllBytes(two + f), Is.EqualTo(File.ReadAllBytes(one + f)), f);
            }
        }
    }
}
