using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// "Shard i of N" of a capture job (<c>-nerfShard i/N</c>): zero-based <see cref="Index"/> so that a job array's
    /// own index (Kubernetes <c>JOB_COMPLETION_INDEX</c>, Slurm <c>SLURM_ARRAY_TASK_ID</c> with <c>--array=0-(N-1)</c>)
    /// can be passed unchanged.
    /// </summary>
    [Serializable]
    public readonly struct ShardSpec : IEquatable<ShardSpec>
    {
        /// <summary>The most shards a dataset may be split into: beyond any job array in practice, and it keeps folder names short.</summary>
        public const int MaxCount = 10000;

        public ShardSpec(int index, int count)
        {
            InvalidParameterException.ThrowIfAny(Validate(index, count).ToArray());
            Index = index;
            Count = count;
        }

        public int Index { get; }
        public int Count { get; }

        /// <summary>The whole dataset as one shard (0/1): what a capture without <c>-nerfShard</c> renders.</summary>
        public static ShardSpec Whole => new ShardSpec(0, 1);

        public bool IsWhole => Count == 1;

        /// <summary>Every problem with shard <paramref name="index"/> of <paramref name="count"/>; empty when 0 ≤ index &lt; count ≤ 10000.</summary>
        public static IReadOnlyList<ValidationProblem> Validate(int index, int count, string field = "nerfShard")
        {
            var problems = new List<ValidationProblem>();
            var value = Format(index, count);
            if (count < 1 || count > MaxCount)
                problems.Add(new ValidationProblem(field, value, "has a shard count N outside [1, " + MaxCount.ToString(CultureInfo.InvariantCulture) + "].",
                    "Give the number of machines of the job array as N, e.g. 0/4 … 3/4 for four machines."));
            else if (index < 0 || index >= count)
                problems.Add(new ValidationProblem(field, value, "has a shard index i outside [0, N-1]: shard indices start at 0.",
                    "Use i from 0 to " + (count - 1).ToString(CultureInfo.InvariantCulture) + ", e.g. Kubernetes' JOB_COMPLETION_INDEX or a Slurm array declared --array=0-" + (count - 1).ToString(CultureInfo.InvariantCulture) + "."));
            return problems;
        }

        /// <summary>Parses "i/N" (whitespace around the numbers allowed). Throws <see cref="InvalidParameterException"/> naming <paramref name="field"/>.</summary>
        public static ShardSpec Parse(string text, string field = "nerfShard")
        {
            if (TryParse(text, out var spec, out var problems, field)) return spec;
            throw new InvalidParameterException(problems);
        }

        public static bool TryParse(string text, out ShardSpec spec, out IReadOnlyList<ValidationProblem> problems, string field = "nerfShard")
        {
            spec = default;
            var parts = (text ?? "").Split('/');
            if (parts.Length != 2
                || !int.TryParse(parts[0].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out var index)
                || !int.TryParse(parts[1].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out var count))
            {
                problems = new[]
                {
                    new ValidationProblem(field, text ?? "(missing)", "is not of the form i/N with whole numbers i and N.",
                        "Write the shard as index/count, e.g. -nerfShard 2/8 for the third of eight machines."),
                };
                return false;
            }
            problems = Validate(index, count, field);
            if (problems.Count > 0) return false;
            spec = new ShardSpec(index, count);
            return true;
        }

        public bool Equals(ShardSpec other) => Index == other.Index && Count == other.Count;
        public override bool Equals(object obj) => obj is ShardSpec other && Equals(other);
        public override int GetHashCode() => HashCode.Combine(Index, Count);
        public static bool operator ==(ShardSpec a, ShardSpec b) => a.Equals(b);
        public static bool operator !=(ShardSpec a, ShardSpec b) => !a.Equals(b);

        /// <summary>"i/N", the form <c>-nerfShard</c> takes.</summary>
        public override string ToString() => Format(Index, Count);

        static string Format(int index, int count) =>
            index.ToString(CultureInfo.InvariantCulture) + "/" + count.ToString(CultureInfo.InvariantCulture);
    }
}
