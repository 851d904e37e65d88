using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// SplitMix64: a tiny, well-studied generator whose sequence for a seed is the same in every runtime.
    /// <see cref="System.Random"/> is not used because its seeded sequence is not specified across .NET, Mono
    /// and IL2CPP, and a dataset must be reproducible from its seed wherever it is planned.
    /// </summary>
    public sealed class SeededRandom
    {
        ulong _state;

        public SeededRandom(long seed) => _state = unchecked((ulong)seed);

        /// <summary>
        /// The generator of <paramref name="seed"/> after <paramref name="draws"/> draws, in constant time: SplitMix64's
        /// state only advances by a fixed step per draw, so the n-th value needs none of the earlier ones.
        /// </summary>
        public static SeededRandom AtDraw(long seed, long draws)
        {
            var random = new SeededRandom(seed);
            random._state = unchecked(random._state + (ulong)draws * Step);
            return random;
        }

        const ulong Step = 0x9E3779B97F4A7C15UL;

        /// <summary>A seed for an independent stream, derived from this seed and a label (e.g. a split name).</summary>
        public static long Derive(long seed, string label)
        {
            // FNV-1a over the label, mixed with the seed through one SplitMix64 step.
            var hash = 14695981039346656037UL;
            foreach (var ch in label ?? "")
            {
                hash ^= ch;
                hash = unchecked(hash * 1099511628211UL);
            }
            var mixer = new SeededRandom(unchecked((long)(hash ^ (ulong)seed)));
            return unchecked((long)mixer.NextUInt64());
        }

        public ulong NextUInt64()
        {
            unchecked
            {
                var z = _state += Step;
                z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
                z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
                return z ^ (z >> 31);
            }
        }

        /// <summary>A uniform double in [0, 1) with 53 random bits.</summary>
        public double NextDouble() => (NextUInt64() >> 11) * (1.0 / (1UL << 53));
    }
}
