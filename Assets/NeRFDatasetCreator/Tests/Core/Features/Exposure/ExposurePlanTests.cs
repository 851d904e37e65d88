using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ExposurePlanTests
    {
        static DatasetSettings Settings(long seed = 7)
        {
            var s = new DatasetSettings { Seed = seed };
            s.Exposure.Mode = ExposureMode.Random;
            s.Exposure.EvMin = -1.5;
            s.Exposure.EvMax = 0.5;
            s.Exposure.GainMin = 0.8;
            s.Exposure.GainMax = 1.25;
            return s;
        }

        [Test]
        public void OffGivesNoPlan()
        {
            Assert.That(ExposurePlan.Of(new DatasetSettings()), Is.Null);
        }

        [Test]
        public void ValuesDependOnlyOnSeedSplitAndIndexAndStayInRange()
        {
            var a = ExposurePlan.Of(Settings());
            var b = ExposurePlan.Of(Settings());
            // Asked in another order (as another shard would): the same values.
            var forward = Enumerable.Range(0, 200).Select(i => a.For(DatasetSplit.Train, i)).ToList();
            var backward = Enumerable.Range(0, 200).Reverse().Select(i => b.For(DatasetSplit.Train, i)).Reverse().ToList();
            Assert.That(backward, Is.EqualTo(forward));
            foreach (var e in forward)
            {
                Assert.That(e.Ev, Is.InRange(-1.5, 0.5));
                Assert.That(e.R, Is.InRange(0.8, 1.25));
                Assert.That(e.B, Is.InRange(0.8, 1.25));
                Assert.That(e.G, Is.EqualTo(1.0));
            }
            // Spread over the range, not a constant: the mean EV of 200 uniform draws is near -0.5.
            Assert.That(forward.Average(e => e.Ev), Is.EqualTo(-0.5).Within(0.15));
            Assert.That(forward.Select(e => e.Ev).Distinct().Count(), Is.EqualTo(200));
            var other = ExposurePlan.Of(Settings(8));
            Assert.That(other.For(DatasetSplit.Train, 3).Ev, Is.Not.EqualTo(a.For(DatasetSplit.Train, 3).Ev));
        }

        [Test]
        public void SplitsNotListedAreUnchanged()
        {
            var plan = ExposurePlan.Of(Settings());
            Assert.That(plan.Applies(DatasetSplit.Train), Is.True);
            Assert.That(plan.Applies(DatasetSplit.Test), Is.False);
            Assert.That(plan.For(DatasetSplit.Test, 4), Is.EqualTo(ViewExposure.Identity));
            Assert.That(plan.WritesClean(DatasetSplit.Train), Is.True);
            Assert.That(plan.WritesClean(DatasetSplit.Val), Is.False);
        }

        [Test]
        public void ListIsCycledByViewIndex()
        {
            var s = new DatasetSettings();
            s.Exposure.Mode = ExposureMode.List;
            s.Exposure.Values = new List<ViewExposure> { new ViewExposure(-1, 1, 1, 1), new ViewExposure(0, 1.1, 1, 0.9), new ViewExposure(1, 1, 1, 1) };
            var plan = ExposurePlan.Of(s);
            Assert.That(Enumerable.Range(0, 7).Select(i => plan.For(DatasetSplit.Train, i).Ev), Is.EqualTo(new double[] { -1, 0, 1, -1, 0, 1, -1 }));
            Assert.That(plan.For(DatasetSplit.Train, 4).R, Is.EqualTo(1.1));
        }

        [Test]
        public void EveryShardWritesTheWholePlansValuesForItsViews()
        {
            var s = Settings();
            s.Train.Count = 9;
            s.Exposure.Test = true;
            var target = new PlanTarget(Vector3d.Zero, 1);
            var whole = Values(CapturePlan.Build(s, target));
            Assert.That(whole, Has.Count.EqualTo(9 + 200));
            using (var temp = new TempFolder())
            {
                var seen = 0;
                for (var k = 0; k < 3; k++)
                {
                    var run = DatasetRun.Prepare(s, target, temp.Path, new ShardSpec(k, 3), "shard-" + k);
                    Assert.That(run.Problems, Is.Empty);
                    foreach (var pair in Values(run.Plan))
                    {
                        Assert.That(pair.Value, Is.EqualTo(whole[pair.Key]), pair.Key);
                        seen++;
                    }
                }
                Assert.That(seen, Is.EqualTo(whole.Count), "the shards cover the plan once");
            }
        }

        /// <summary>(exposure_ev, r, g, b) per file_path of the train and test transforms files the plan writes.</summary>
        static Dictionary<string, double[]> Values(CapturePlan plan)
        {
            var values = new Dictionary<string, double[]>();
            foreach (var split in new[] { DatasetSplit.Train, DatasetSplit.Test })
                foreach (Newtonsoft.Json.Linq.JObject frame in Newtonsoft.Json.Linq.JObject.Parse(BlenderTransformsWriter.Write(plan, split))["frames"])
                {
                    var wb = frame["white_balance"].ToObject<double[]>();
                    values.Add((string)frame["file_path"], new[] { (double)frame["exposure_ev"], wb[0], wb[1], wb[2] });
                }
            return values;
        }

        [Test]
        public void CleanFileIsPlannedOnlyForModifiedSplits()
        {
            var s = Settings();
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Train), Has.Member(DatasetFileKind.CleanColor));
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Test), Has.No.Member(DatasetFileKind.CleanColor));
            s.Exposure.WriteClean = false;
            Assert.That(DatasetLayout.FileKinds(s, DatasetSplit.Train), Has.No.Member(DatasetFileKind.CleanColor));
            Assert.That(DatasetLayout.RelativePath(DatasetSplit.Train, 7, DatasetFileKind.CleanColor), Is.EqualTo("train/r_7_clean.png"));
        }
    }
}
