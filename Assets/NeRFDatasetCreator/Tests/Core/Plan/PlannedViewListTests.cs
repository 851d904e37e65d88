using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A plan's views are made on demand (PlannedViewList): nothing is kept between reads, and every way of reading them
    /// — by index, enumerated, by split, a shard's share — gives the same views in the same order.
    /// </summary>
    [TestFixture]
    public class PlannedViewListTests
    {
        static CapturePlan Plan()
        {
            var s = new DatasetSettings { Seed = 5 };
            s.Train.Count = 50;
            s.Val.Count = 20;
            s.Test.Count = 30;
            return CapturePlan.Build(s, PlanTarget.AtOrigin);
        }

        static string Key(PlannedView v) => v.Split + " " + v.Index + " " + v.TransformMatrix + " " + v.Pose.Position + " " + v.Pose.Rotation;

        [Test]
        public void EachReadMakesANewViewWithTheSameValues()
        {
            var plan = Plan();
            var a = plan.Views[42];
            var b = plan.Views[42];
            Assert.That(b, Is.Not.SameAs(a), "the plan keeps no view between reads");
            Assert.That(Key(b), Is.EqualTo(Key(a)));
        }

        [Test]
        public void IndexEnumerationSplitsAndCopiesAgree()
        {
            var plan = Plan();
            var byIndex = Enumerable.Range(0, plan.Views.Count).Select(i => Key(plan.Views[i])).ToList();
            Assert.That(byIndex.Count, Is.EqualTo(100));
            Assert.That(plan.Views.Select(Key), Is.EqualTo(byIndex));
            Assert.That(plan.Views.ToList().Select(Key), Is.EqualTo(byIndex)); // ICollection.CopyTo
            Assert.That(DatasetSplits.All.SelectMany(s => plan.ViewsOf(s)).Select(Key), Is.EqualTo(byIndex));
            Assert.That(plan.ViewsOf(DatasetSplit.Val).Count, Is.EqualTo(20));
            Assert.That(plan.ViewsOf(DatasetSplit.Val).Select(v => v.Index), Is.EqualTo(Enumerable.Range(0, 20)));
            Assert.That(((ICollection<PlannedView>)plan.Views).Contains(plan.Views[70]), Is.True);
        }

        [Test]
        public void AShardsShareIsTheFilteredViewsInOrder()
        {
            var plan = Plan();
            var shard = plan.Only(v => v.Index % 7 == 3);
            var expected = plan.Views.Where(v => v.Index % 7 == 3).Select(Key).ToList();
            Assert.That(shard.Views.Select(Key), Is.EqualTo(expected));
            Assert.That(shard.ViewsOf(DatasetSplit.Test).Select(Key), Is.EqualTo(plan.ViewsOf(DatasetSplit.Test).Where(v => v.Index % 7 == 3).Select(Key)));
            Assert.That(shard.ViewsOf(DatasetSplit.Test).Select(v => v.Index), Is.EqualTo(new[] { 3, 10, 17, 24 }));
        }

        [Test]
        public void OneRandomDirectionNeedsNoneBeforeIt()
        {
            // SplitMix64 after k draws, reached in one step, equals drawing k times.
            var walked = new SeededRandom(-77);
            for (var k = 0; k < 1001; k++) walked.NextUInt64();
            Assert.That(SeededRandom.AtDraw(-77, 1001).NextUInt64(), Is.EqualTo(walked.NextUInt64()));
            // Direction i of a whole-sphere random formation: heights −1 + 2u and azimuths 2πu from draws 2i and 2i + 1 of the seed's stream.
            var formation = new RandomFormation(123, upperHemisphereOnly: false);
            var stream = new SeededRandom(123);
            for (var i = 0; i < 5000; i++)
            {
                var height = -1 + 2 * stream.NextDouble();
                var azimuth = 2 * System.Math.PI * stream.NextDouble();
                if (i % 1249 != 0) continue;
                var one = formation.Direction(i, 5000);
                Assert.That(one.ElevationRadians, Is.EqualTo(System.Math.Asin(height)));
                Assert.That(one.AzimuthRadians, Is.EqualTo(azimuth));
            }
        }
    }
}
