using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which shard renders which view: view k of the global plan order (train, then val, then test) belongs to
    /// shard k mod N — round-robin, not contiguous blocks. Why: the cost of a view is not uniform. Splits can differ
    /// (a test split with extra depth/normal passes, a val split at another resolution of detail), and neighbouring
    /// views of a formation see the same side of the target (an orbit's close-up arc, a semi-sphere's dense top).
    /// Blocks would hand one machine all of the test split or all of one arc; round-robin gives every shard every
    /// split and every part of every formation, with view counts that differ by at most one per split. It also needs
    /// nothing but k and N, so every machine computes the same answer alone, and a lost shard leaves evenly spread
    /// gaps rather than a missing side.
    /// </summary>
    public static class ShardAssignment
    {
        /// <summary>The shard (0…N−1) that renders global view <paramref name="globalIndex"/>.</summary>
        public static int ShardOf(int globalIndex, int shardCount)
        {
            if (globalIndex < 0) throw new ArgumentOutOfRangeException(nameof(globalIndex), globalIndex, "View indices start at 0.");
            if (shardCount < 1) throw new ArgumentOutOfRangeException(nameof(shardCount), shardCount, "There is at least one shard.");
            return globalIndex % shardCount;
        }

        /// <summary>Whether view <paramref name="index"/> of <paramref name="split"/> belongs to <paramref name="shard"/>.</summary>
        public static bool Contains(ShardSpec shard, ViewCounts counts, string split, int index)
        {
            if (counts == null) throw new ArgumentNullException(nameof(counts));
            if (index < 0 || index >= counts.Of(split))
                throw new ArgumentOutOfRangeException(nameof(index), index, "The plan's " + split + " split has " + counts.Of(split) + " views.");
            return ShardOf(counts.OffsetOf(split) + index, shard.Count) == shard.Index;
        }

        /// <summary>The indices within <paramref name="split"/> (ascending) that <paramref name="shard"/> renders.</summary>
        public static IReadOnlyList<int> IndicesInSplit(ShardSpec shard, ViewCounts counts, string split)
        {
            if (counts == null) throw new ArgumentNullException(nameof(counts));
            var offset = counts.OffsetOf(split);
            var count = counts.Of(split);
            var indices = new List<int>();
            // First index i ≥ 0 with (offset + i) mod N == shard.Index, then every N-th.
            var first = ((shard.Index - offset) % shard.Count + shard.Count) % shard.Count;
            for (var i = first; i < count; i += shard.Count) indices.Add(i);
            return indices;
        }
    }
}
