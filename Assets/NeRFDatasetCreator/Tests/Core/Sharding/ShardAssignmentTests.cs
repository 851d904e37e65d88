using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ShardAssignmentTests
    {
        // Plan train 5, val 3, test 4 = global views 0…11; val starts at 5, test at 8. Shard of view k is k mod 3.
        static readonly ViewCounts Small = new ViewCounts(5, 3, 4);

        [TestCase(0, "train", new[] { 0, 3 })]
        [TestCase(1, "train", new[] { 1, 4 })]
        [TestCase(2, "train", new[] { 2 })]
        [TestCase(0, "val", new[] { 1 })]      // global 6
        [TestCase(1, "val", new[] { 2 })]      // global 7
        [TestCase(2, "val", new[] { 0 })]      // global 5
        [TestCase(0, "test", new[] { 1 })]     // global 9
        [TestCase(1, "test", new[] { 2 })]     // global 10
        [TestCase(2, "test", new[] { 0, 3 })]  // global 8, 11
        public void ViewKOfThePlanGoesToShardKModN(int shard, string split, int[] expected)
        {
            Assert.That(ShardAssignment.IndicesInSplit(new ShardSpec(shard, 3), Small, split), Is.EqualTo(expected));
            foreach (var i in expected)
                Assert.That(ShardAssignment.Contains(new ShardSpec(shard, 3), Small, split, i), Is.True);
        }

        [TestCase(1)]
        [TestCase(7)]
        [TestCase(400)]
        [TestCase(1000)]
        public void EveryViewBelongsToExactlyOneShardAndSplitsAreBalancedWithinOne(int shardCount)
        {
            var counts = new ViewCounts(100, 100, 200);
            foreach (var split in ViewCounts.SplitNames)
            {
                var perShard = Enumerable.Range(0, shardCount)
                    .Select(s => ShardAssignment.IndicesInSplit(new ShardSpec(s, shardCount), counts, split)).ToList();
                var all = perShard.SelectMany(x => x).OrderBy(i => i).ToList();
                Assert.That(all, Is.EqualTo(Enumerable.Range(0, counts.Of(split)).ToList()), split);
                Assert.That(perShard.Max(x => x.Count) - perShard.Min(x => x.Count), Is.LessThanOrEqualTo(1), split);
            }
        }

        [Test]
        public void TheWholeDatasetIsShardZeroOfOne()
        {
            Assert.That(ShardAssignment.IndicesInSplit(ShardSpec.Whole, Small, "test"), Is.EqualTo(new[] { 0, 1, 2, 3 }));
            Assert.That(ShardSpec.Whole.IsWhole, Is.True);
        }

        [TestCase("2/8", 2, 8)]
        [TestCase(" 0 / 1 ", 0, 1)]
        [TestCase("9999/10000", 9999, 10000)]
        public void ParsesIndexSlashCount(string text, int index, int count)
        {
            var spec = ShardSpec.Parse(text);
            Assert.That(spec.Index, Is.EqualTo(index));
            Assert.That(spec.Count, Is.EqualTo(count));
            Assert.That(ShardSpec.Parse(spec.ToString()), Is.EqualTo(spec));
        }

        [TestCase("8/8", "shard index i outside [0, N-1]")]
        [TestCase("0/0", "shard count N outside [1, 10000]")]
        [TestCase("0/10001", "shard count N outside [1, 10000]")]
        [TestCase("-1/4", "not of the form i/N")]
        [TestCase("1-4", "not of the form i/N")]
        [TestCase("", "not of the form i/N")]
        [TestCase(null, "not of the form i/N")]
        public void RefusesBadShardsNamingTheArgument(string text, string reason)
        {
            var e = Assert.Throws<InvalidParameterException>(() => ShardSpec.Parse(text));
            Assert.That(e.Problems, Has.Count.EqualTo(1));
            Assert.That(e.Problems[0].Field, Is.EqualTo("nerfShard"));
            Assert.That(e.Problems[0].Reason, Does.Contain(reason));
            Assert.That(e.Problems[0].Fix, Is.Not.Empty);
        }

        [Test]
        public void ValidateReportsAnIndexPastTheEndWithTheValidRange()
        {
            var problems = ShardSpec.Validate(4, 4);
            Assert.That(problems, Has.Count.EqualTo(1));
            Assert.That(problems[0].Value, Is.EqualTo("4/4"));
            Assert.That(problems[0].Fix, Does.Contain("from 0 to 3"));
            Assert.That(ShardSpec.Validate(3, 4), Is.Empty);
        }
    }
}
