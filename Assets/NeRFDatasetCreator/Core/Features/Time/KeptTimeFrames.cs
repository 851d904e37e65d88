using System;
using System.Collections;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <see cref="TimeDatasetChecks.Keep"/> kept of each frame of a transforms file, in order, holding only the
    /// frames that kept something: every other frame reads as the one shared frame without time keys. A static dataset of
    /// 300 000 frames then costs a count, not a list of 300 000 references; a dynamic one keeps its frames' time keys.
    /// </summary>
    sealed class KeptTimeFrames : IReadOnlyList<TimeDatasetChecks.Kept>
    {
        readonly List<int> _indices = new List<int>();
        readonly List<TimeDatasetChecks.Kept> _kept = new List<TimeDatasetChecks.Kept>();

        public int Count { get; private set; }

        /// <summary>Appends the next frame's <see cref="TimeDatasetChecks.Keep"/> result.</summary>
        public void Add(TimeDatasetChecks.Kept kept)
        {
            if (!ReferenceEquals(kept, TimeDatasetChecks.NoTime))
            {
                _indices.Add(Count);
                _kept.Add(kept);
            }
            Count++;
        }

        public TimeDatasetChecks.Kept this[int index]
        {
            get
            {
                if ((uint)index >= (uint)Count) throw new ArgumentOutOfRangeException(nameof(index));
                var at = _indices.BinarySearch(index);
                return at >= 0 ? _kept[at] : TimeDatasetChecks.NoTime;
            }
        }

        public IEnumerator<TimeDatasetChecks.Kept> GetEnumerator()
        {
            var next = 0;
            for (var i = 0; i < Count; i++)
                yield return next < _indices.Count && _indices[next] == i ? _kept[next++] : TimeDatasetChecks.NoTime;
        }

        IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
    }
}
