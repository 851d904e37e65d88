using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A motion-blurred capture rendered in two shards and merged (issue 32 item 20) is the capture rendered whole: the
    /// same frames (shutter keys and sharp_path included), the same files byte for byte (the sharp images included), the
    /// same top-level shutter keys; it validates and passes the motion blur check.
    /// </summary>
    [TestFixture]
    public class BlurredShardsMergeTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        static AnalyticDataset.Options Options(double readout, ShardSpec shard, string folder) => new AnalyticDataset.Options
        {
            Width = 48, Height = 36, Supersampling = 2, Train = 4, Val = 2, Test = 1, PointCloud = 0, Shard = shard, DatasetFolder = folder,
            MotionBlur = new MotionBlurSettings
            {
                Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.25, ShakeDegrees = 2, SubFrames = 8, Readout = readout,
            },
        };

        [TestCase(0.0, TestName = "BlurredShardsMerge_GlobalShutter")]
        [TestCase(0.4, TestName = "BlurredShardsMerge_RollingShutter")]
        public void TwoBlurredShardsMergeIntoTheWholeCapture(double readout)
        {
            var whole = AnalyticDataset.Write(_temp.Path, "blur", Options(readout, default, Path.Combine("whole", "blur")));
            var shards = new List<string>();
            for (var i = 0; i < 2; i++)
                shards.Add(AnalyticDataset.Write(_temp.Path, "blur", Options(readout, new ShardSpec(i, 2), Path.Combine("shards", "shard-" + i))));
            var merged = Path.Combine(_temp.Path, "merged");
            var result = ShardMerger.Merge(shards, merged);
            Assert.That(result.Problems.Select(p => p.ToString()), Is.Empty);

            foreach (var split in DatasetSplits.Names)
            {
                var a = JObject.Parse(File.ReadAllText(Path.Combine(whole, DatasetLayout.TransformsFileName(split))));
                var b = JObject.Parse(File.ReadAllText(Path.Combine(merged, DatasetLayout.TransformsFileName(split))));
                Assert.That(JToken.DeepEquals(a["frames"], b["frames"]), Is.True, split + ": the merged frames are the whole capture's\n" + b["frames"]);
                foreach (var key in new[] { "rolling_shutter", "camera_angle_x" })
                    Assert.That(JToken.DeepEquals(a[key], b[key]), Is.True, split + " " + key);
                var sharp = ((JArray)b["frames"]).Count(f => f[MotionBlurKeys.SharpPath] != null && f[MotionBlurKeys.Start] != null && f[MotionBlurKeys.End] != null);
                Assert.That(sharp, Is.EqualTo(((JArray)b["frames"]).Count), split + ": every frame keeps its sharp image and shutter poses");
                foreach (var file in Directory.GetFiles(Path.Combine(whole, split)))
                {
                    var copy = Path.Combine(merged, split, Path.GetFileName(file));
                    Assert.That(File.Exists(copy), Is.True, copy);
                    Assert.That(File.ReadAllBytes(copy), Is.EqualTo(File.ReadAllBytes(file)), copy);
                }
            }
            Assert.That(Directory.GetFiles(Path.Combine(merged, "train"), "*_sharp_0000.png").Length, Is.EqualTo(4));
            Assert.That(DatasetValidator.Validate(merged).Problems.Select(p => p.ToString()), Is.Empty);
            var report = DatasetCheck.Run(merged, new DatasetCheckOptions());
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12));
            Assert.That(report.Results.Single(r => r.Name == "motion blur").Status, Is.EqualTo(DatasetCheckStatus.Passed), text);
            Assert.That(report.Failed, Is.False, text);
        }
    }
}
