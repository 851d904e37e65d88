using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// check's <b>flow</b> on analytic dynamic datasets with flow/ written by FlowWriter: the untouched flow passes
    /// (monocular and multi-view, EXR or PNG depth), and each planted fault — the sign flipped, dx and dy exchanged, a
    /// pair's files one time step off, a mask inverted, a file missing — fails with a problem naming the file and the pair.
    /// </summary>
    public class FlowCheckTests
    {
        static AnalyticDataset.Options Options(bool monocular, ExtraOutput depth = ExtraOutput.PngAndExr, int width = 64) => new AnalyticDataset.Options
        {
            Width = width, Height = width * 3 / 4, Supersampling = 1, Train = monocular ? 5 : 2, Val = 1, Test = 1,
            TimeSteps = monocular ? 5 : 3, Monocular = monocular, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            Configure = s => { foreach (var split in new[] { s.Train, s.Val, s.Test }) split.Depth = depth; },
        };

        static string WithFlow(TempFolder temp, string name, bool monocular, ExtraOutput depth = ExtraOutput.PngAndExr, int width = 64)
        {
            var folder = AnalyticDataset.Write(temp.Path, name, Options(monocular, depth, width));
            FlowWriter.Write(folder, new FlowSettings { On = true, TrackQueryFrames = new[] { 0 }, TrackStride = 4 });
            return folder;
        }

        static DatasetCheckResult Flow(DatasetCheckReport report) => report.Results.Single(r => r.Name == FlowCheck.CheckName);

        static string Lines(DatasetCheckReport report) => string.Join("\n", report.SummaryLines.Concat(report.Problems.Select(p => p.ToString())));

        // 128 × 96: at 64 × 48 some monocular pairs have fewer than MinJudged pixels visible both ways. 400 × 300: enough
        // pixels just behind the opaque sphere's limb (hidden by a surface < 1 % nearer) to fail an occlusion tolerance of
        // 1 % for occluded pixels (1.15 % of a pair) — occluded needs only the depths' uncertainties.
        [TestCase(true, ExtraOutput.PngAndExr, 400)]
        [TestCase(false, ExtraOutput.PngAndExr, 128)]
        [TestCase(true, ExtraOutput.Png, 128)]
        public void TheAnalyticFlowPassesEveryMeasurement(bool monocular, ExtraOutput depth, int width)
        {
            using (var temp = new TempFolder())
            {
                var folder = WithFlow(temp, "clean", monocular, depth, width);
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                var flow = Flow(report);
                Assert.That(flow.Status, Is.EqualTo(DatasetCheckStatus.Passed), Lines(report));
                Assert.That(report.Problems.Where(p => p.Check == FlowCheck.CheckName), Is.Empty, Lines(report));
                // The figure counts the pairs each measurement judged: every pair against depth and poses and against b's
                // depth; forward ∘ backward where 20 or more pixels are visible both ways (a monocular plan spreads its
                // views over the sphere, so two consecutive ones may share little).
                var pairs = FlowRecord.Read(folder).Pairs.Count;
                Assert.That(flow.Figure, Does.StartWith(pairs + " pairs; "));
                Assert.That(flow.Figure, Does.Contain("(" + pairs + " judged)").And.Contain("b's depth (" + pairs + ")"), flow.Figure);
                var inverse = int.Parse(System.Text.RegularExpressions.Regex.Match(flow.Figure, @"forward ∘ backward \((\d+)\)").Groups[1].Value);
                Assert.That(inverse, Is.GreaterThanOrEqualTo(pairs - 1), flow.Figure);
            }
        }

        [Test]
        public void ADatasetWithoutFlowDoesNotListTheCheck()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "plain", Options(true));
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                Assert.That(report.Results.Select(r => r.Name), Does.Not.Contain(FlowCheck.CheckName));
            }
        }

        // Each planted fault, on one pair's file(s): the problem names the file and the pair "train 0 → 1" (monocular) or
        // "train_cam00 0 → 1" (multi-view, static cameras: only the moving sphere has flow).
        public enum Fault { SignFlipped, AxesSwapped, OneStepOff, OccludedInverted, OutsideInverted }

        [TestCase(Fault.SignFlipped, true)]
        [TestCase(Fault.SignFlipped, false)]
        [TestCase(Fault.AxesSwapped, true)]
        [TestCase(Fault.AxesSwapped, false)]
        [TestCase(Fault.OneStepOff, true)]
        [TestCase(Fault.OneStepOff, false)]
        [TestCase(Fault.OccludedInverted, true)]
        [TestCase(Fault.OutsideInverted, false)]
        public void APlantedFaultIsCaughtNamingTheFileAndThePair(Fault fault, bool monocular)
        {
            using (var temp = new TempFolder())
            {
                var folder = WithFlow(temp, "faulty", monocular);
                var video = monocular ? "train" : "train_cam00";
                var pair = new FlowPair(video, 0, 1);
                var file = Plant(folder, fault, pair);
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                Assert.That(Flow(report).Status, Is.EqualTo(DatasetCheckStatus.Failed), Lines(report));
                var named = report.Problems.Where(p => p.Check == FlowCheck.CheckName && p.File == "./" + file && p.Message.StartsWith("pair " + video + " 0 → 1 (", StringComparison.Ordinal)).ToList();
                Assert.That(named, Is.Not.Empty, Lines(report));
                // The other pairs are untouched: only the pair and its reverse (which reads it for forward ∘ backward) are named.
                Assert.That(report.Problems.Where(p => p.Check == FlowCheck.CheckName).All(p => p.Message.StartsWith("pair " + video + " 0 → 1 ", StringComparison.Ordinal) || p.Message.StartsWith("pair " + video + " 1 → 0 ", StringComparison.Ordinal)), Is.True, Lines(report));
            }
        }

        /// <summary>Plants the fault in <paramref name="pair"/>'s files; returns the file the problem must name.</summary>
        static string Plant(string folder, Fault fault, FlowPair pair)
        {
            string Full(string relative) => Path.Combine(folder, relative.Replace('/', Path.DirectorySeparatorChar));
            switch (fault)
            {
                case Fault.SignFlipped:
                case Fault.AxesSwapped:
                {
                    var flow = FloFile.Read(Full(pair.FlowFile), out var w, out var h);
                    for (var p = 0; p < w * h; p++)
                    {
                        float dx = flow[2 * p], dy = flow[2 * p + 1];
                        if (fault == Fault.SignFlipped) { flow[2 * p] = -dx; flow[2 * p + 1] = -dy; }
                        else { flow[2 * p] = dy; flow[2 * p + 1] = dx; }
                    }
                    File.WriteAllBytes(Full(pair.FlowFile), FloFile.Encode(flow, w, h));
                    return pair.FlowFile;
                }
                case Fault.OneStepOff:
                {
                    // The pair's files hold the next pair's (1 → 2): a writer one time step off.
                    var next = new FlowPair(pair.Video, pair.From + 1, pair.To + 1);
                    foreach (var (of, to) in new[] { (next.FlowFile, pair.FlowFile), (next.OccludedFile, pair.OccludedFile), (next.OutsideFile, pair.OutsideFile), (next.SceneFlowFile, pair.SceneFlowFile) })
                        File.Copy(Full(of), Full(to), overwrite: true);
                    return pair.FlowFile;
                }
                default:
                {
                    var mask = fault == Fault.OccludedInverted ? pair.OccludedFile : pair.OutsideFile;
                    var png = PngReader.Read(Full(mask));
                    var inverted = png.Samples.Select(b => (byte)(255 - b)).ToArray();
                    File.WriteAllBytes(Full(mask), PngWriter.Encode(inverted, png.Width, png.Height, PngPixelFormat.Gray8));
                    return mask;
                }
            }
        }

        [Test]
        public void FlowRecordedInTheConfigButLostFails()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "lost-record", Options(true));
                var config = Path.Combine(folder, DatasetLayout.ConfigFileName);
                var json = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(config));
                json["flow"] = new Newtonsoft.Json.Linq.JObject { ["record"] = FlowLayout.RecordFile, ["pairs"] = 8 };
                File.WriteAllText(config, json.ToString());
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                Assert.That(Flow(report).Status, Is.EqualTo(DatasetCheckStatus.Failed), Lines(report));
                Assert.That(report.Problems.Select(p => p.ToString()), Has.Some.StartWith("./flow/flow.json [flow]: dataset_config.json records flow (\"flow\"), but flow/flow.json is missing."), Lines(report));
            }
        }

        [Test]
        public void AnUnreadableDepthEndsNoCheckRun()
        {
            using (var temp = new TempFolder())
            {
                var folder = WithFlow(temp, "bad-depth", true, ExtraOutput.Png);
                // Frame 1's depth PNG rewritten as 8-bit grey: the dataset check names it; flow compares no pair with it
                // and the run ends with a report (never an exception).
                var depth = Path.Combine(folder, "train", "r_1_depth_0000.png");
                var png = PngReader.Read(depth);
                File.WriteAllBytes(depth, PngWriter.Encode(new byte[png.Width * png.Height], png.Width, png.Height, PngPixelFormat.Gray8));
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                Assert.That(report.Failed, Is.True);
                Assert.That(report.Problems.Select(p => p.ToString()), Has.Some.Contains("r_1_depth_0000.png"), Lines(report));
                Assert.That(Flow(report).Status, Is.Not.EqualTo(DatasetCheckStatus.Skipped), Lines(report));
            }
        }

        [Test]
        public void AMissingOrWrongSizedFileIsNamed()
        {
            using (var temp = new TempFolder())
            {
                var folder = WithFlow(temp, "lost", true);
                var pair = new FlowPair("train", 2, 3);
                File.Delete(Path.Combine(folder, pair.OccludedFile));
                var other = new FlowPair("train", 3, 2);
                File.WriteAllBytes(Path.Combine(folder, other.FlowFile), FloFile.Encode(new float[2 * 32 * 48], 32, 48));
                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                Assert.That(Flow(report).Status, Is.EqualTo(DatasetCheckStatus.Failed));
                Assert.That(report.Problems.Select(p => p.ToString()), Has.Some.EqualTo("./" + pair.FlowFile + " [flow]: pair train 2 → 3 (train/r_2.png → train/r_3.png): " + pair.OccludedFile + " is missing."), Lines(report));
                Assert.That(report.Problems.Select(p => p.ToString()), Has.Some.EqualTo("./" + other.FlowFile + " [flow]: pair train 3 → 2 (train/r_3.png → train/r_2.png): " + other.FlowFile + " is 32 × 48 pixels, its frame's image 64 × 48."), Lines(report));
            }
        }
    }
}
