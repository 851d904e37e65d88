using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class TimePlanningTests
    {
        static DatasetSettings Monocular(int train, int val, int test, double start = 0, double end = 2)
        {
            var s = new DatasetSettings { Seed = 3, Loaders = TargetLoaders.GaussianSplatting }; // needs only train: splits may be empty
            s.Train.Count = train;
            s.Val.Count = val;
            s.Test.Count = test;
            s.Time.Mode = TimeMode.Monocular;
            s.Time.StartSeconds = start;
            s.Time.EndSeconds = end;
            return s;
        }

        static DatasetSettings MultiView(int train, int val, int test, int steps, double start = 0, double end = 1)
        {
            var s = Monocular(train, val, test, start, end);
            s.Time.Mode = TimeMode.MultiView;
            s.Time.Steps = steps;
            return s;
        }

        static double[] Times(CapturePlan plan, DatasetSplit split) => plan.ViewsOf(split).Select(v => v.Time.Value.Normalised).ToArray();
        static double[] Seconds(CapturePlan plan, DatasetSplit split) => plan.ViewsOf(split).Select(v => v.Time.Value.Seconds).ToArray();

        [Test]
        public void StaticPlansHaveNoTime()
        {
            var plan = CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin);
            Assert.That(plan.Time, Is.Null);
            Assert.That(plan.Views.All(v => v.Time == null), Is.True);
        }

        [Test]
        public void MonocularTrainViewsSpreadOverTheRangeInOrder()
        {
            // 5 train views over 1–3 s: steps at 0, ¼, ½, ¾, 1 → 1, 1.5, 2, 2.5, 3 s.
            var plan = CapturePlan.Build(Monocular(5, 0, 0, 1, 3), PlanTarget.AtOrigin);
            Assert.That(Times(plan, DatasetSplit.Train), Is.EqualTo(new[] { 0, 0.25, 0.5, 0.75, 1.0 }));
            Assert.That(Seconds(plan, DatasetSplit.Train), Is.EqualTo(new[] { 1, 1.5, 2, 2.5, 3.0 }));
            Assert.That(plan.ViewsOf(DatasetSplit.Train).Select(v => v.Time.Value.Step), Is.EqualTo(new[] { 0, 1, 2, 3, 4 }));
            Assert.That(plan.Time.Steps, Is.EqualTo(5));
        }

        [Test]
        public void MonocularTestViewsStartAtZeroThenSitBetweenTrainTimes()
        {
            // Train at k/4. Test (M = 5): view 0 at 0 (D-NeRF asserts it); view j at midpoint k = ⌊(j − ½)·4/4⌋ → (k + ½)/4.
            var plan = CapturePlan.Build(Monocular(5, 3, 5), PlanTarget.AtOrigin);
            Assert.That(Times(plan, DatasetSplit.Test), Is.EqualTo(new[] { 0, 0.125, 0.375, 0.625, 0.875 }));
            // Val (M = 3): k = ⌊(j − ½)·4/2⌋ = 1, 3 → 0.375, 0.875.
            Assert.That(Times(plan, DatasetSplit.Val), Is.EqualTo(new[] { 0, 0.375, 0.875 }));
            var train = Times(plan, DatasetSplit.Train);
            foreach (var t in Times(plan, DatasetSplit.Test).Skip(1)) Assert.That(train, Has.No.Member(t));
            Assert.That(Seconds(plan, DatasetSplit.Test)[1], Is.EqualTo(0.25), "0.125 of 0–2 s");
            Assert.That(plan.ViewsOf(DatasetSplit.Test).Skip(1).All(v => v.Time.Value.Step == -1), Is.True);
        }

        [Test]
        public void MonocularViewsKeepTheirFormationPoseAndFileIndex()
        {
            var timed = CapturePlan.Build(Monocular(6, 2, 2), PlanTarget.AtOrigin);
            var still = Monocular(6, 2, 2);
            still.Time.Mode = TimeMode.Static;
            var plain = CapturePlan.Build(still, PlanTarget.AtOrigin);
            Assert.That(timed.Views.Select(v => v.FramePath), Is.EqualTo(plain.Views.Select(v => v.FramePath)));
            Assert.That(timed.Views.Select(v => v.TransformMatrix), Is.EqualTo(plain.Views.Select(v => v.TransformMatrix)));
        }

        [Test]
        public void MultiViewPutsEveryCameraAtEveryStep()
        {
            var plan = CapturePlan.Build(MultiView(3, 1, 2, 4, 0, 1.5), PlanTarget.AtOrigin);
            var train = plan.ViewsOf(DatasetSplit.Train).ToList();
            Assert.That(train, Has.Count.EqualTo(12));
            // View k·3 + c is camera c at step k: r_7 is camera 1 at step 2, time 2/3, 1 s.
            Assert.That(train[7].FramePath, Is.EqualTo("./train/r_7"));
            Assert.That(train[7].Time.Value.Camera, Is.EqualTo(1));
            Assert.That(train[7].Time.Value.Step, Is.EqualTo(2));
            Assert.That(train[7].Time.Value.Normalised, Is.EqualTo(2 / 3.0));
            Assert.That(train[7].Time.Value.Seconds, Is.EqualTo(1.0));
            Assert.That(train[7].TransformMatrix, Is.EqualTo(train[1].TransformMatrix), "a camera keeps its pose at every step");
            Assert.That(plan.ViewsOf(DatasetSplit.Test).Count(), Is.EqualTo(8));
            Assert.That(TimePlanning.ViewCount(plan.Settings, plan.Time, DatasetSplit.Test), Is.EqualTo(8));
        }

        [Test]
        public void FpsPlacesStepsOnTheFrameGridAndEndsOnTheLastFrame()
        {
            // 30 fps over 0.5–0.6 s: frames at 0.5 + k/30 up to 0.6 → k = 0..3 (0.6 itself is frame 3), 4 steps.
            var s = MultiView(1, 0, 0, 0, 0.5, 0.6);
            s.Time.Fps = 30;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            Assert.That(plan.Time.Steps, Is.EqualTo(4));
            Assert.That(Seconds(plan, DatasetSplit.Train), Is.EqualTo(new[] { 0.5, 0.5 + 1 / 30.0, 0.5 + 2 / 30.0, 0.5 + 3 / 30.0 }));
            // An end between frames: 0.55 s keeps frames 0 and 1, and the range ends on frame 1.
            s.Time.EndSeconds = 0.55;
            plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            Assert.That(plan.Time.Steps, Is.EqualTo(2));
            Assert.That(plan.Time.EndSeconds, Is.EqualTo(0.5 + 1 / 30.0));
            Assert.That(Times(plan, DatasetSplit.Train), Is.EqualTo(new[] { 0, 1.0 }));
        }

        [Test]
        public void ClipLengthEndNeedsTheMeasuredLength()
        {
            var s = MultiView(2, 0, 0, 3);
            s.Time.EndAtClipLength = true;
            var problems = CapturePlan.Check(s, PlanTarget.AtOrigin);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "time.end" }));
            Assert.That(problems[0].Value, Is.EqualTo("\"clip\""));
            var plan = CapturePlan.Build(s, new PlanTarget(Vector3d.Zero, 0, 2.5));
            Assert.That(plan.Time.EndSeconds, Is.EqualTo(2.5));
            Assert.That(Seconds(plan, DatasetSplit.Train), Is.EqualTo(new[] { 0, 0, 1.25, 1.25, 2.5, 2.5 }));
        }

        [Test]
        public void MonocularFpsMustMatchTheTrainCount()
        {
            var s = Monocular(10, 0, 0, 0, 1);
            s.Time.Fps = 4; // 5 frames
            var problems = CapturePlan.Check(s, PlanTarget.AtOrigin);
            Assert.That(problems.Select(p => p.Field), Is.EqualTo(new[] { "splits.train.count" }));
            Assert.That(problems[0].Fix, Does.Contain("to 5"));
            s.Train.Count = 5;
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin), Is.Empty);
        }

        [Test]
        public void MultiViewSplitsMayNotExceedTheViewLimit()
        {
            var s = MultiView(DatasetSettings.MaxViews / 10 + 1, 0, 0, 10);
            Assert.That(CapturePlan.Check(s, PlanTarget.AtOrigin).Select(p => p.Field), Is.EqualTo(new[] { "splits.train.count" }));
        }

        [Test]
        public void ShardsSplitTheTimedViews()
        {
            using (var temp = new TempFolder())
            {
                var s = MultiView(2, 0, 1, 3);
                var whole = DatasetRun.Prepare(s, PlanTarget.AtOrigin, temp.Path, ShardSpec.Whole, temp.Combine("d"));
                var shards = Enumerable.Range(0, 2).Select(i => DatasetRun.Prepare(s, PlanTarget.AtOrigin, temp.Path, new ShardSpec(i, 2), temp.Combine("d" + i))).ToList();
                var shardViews = shards.SelectMany(r => r.Plan.Views).Select(v => v.FramePath).OrderBy(p => p).ToList();
                Assert.That(shardViews, Is.EqualTo(whole.Plan.Views.Select(v => v.FramePath).OrderBy(p => p).ToList()));
                Assert.That(whole.Plan.Views, Has.Count.EqualTo(9));
            }
        }

        [Test]
        public void PlansAreDeterministic()
        {
            var a = CapturePlanJson.Write(CapturePlan.Build(MultiView(3, 2, 2, 5), PlanTarget.AtOrigin));
            var b = CapturePlanJson.Write(CapturePlan.Build(MultiView(3, 2, 2, 5), PlanTarget.AtOrigin));
            Assert.That(a, Is.EqualTo(b));
            var m1 = BlenderTransformsWriter.Write(CapturePlan.Build(Monocular(7, 3, 4), PlanTarget.AtOrigin), DatasetSplit.Test);
            var m2 = BlenderTransformsWriter.Write(CapturePlan.Build(Monocular(7, 3, 4), PlanTarget.AtOrigin), DatasetSplit.Test);
            Assert.That(m1, Is.EqualTo(m2));
        }
    }
}
