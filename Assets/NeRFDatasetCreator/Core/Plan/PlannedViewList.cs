using System;
using System.Collections;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A plan's views — train, then val, then test, each by index — made on demand from the splits' placement
    /// (<see cref="PlanSplitViews"/>) rather than held: a plan of 300 000 views costs the same memory as one of 30, and
    /// the JSON files, the rig preview and the warnings are written view by view. Each access makes a new
    /// <see cref="PlannedView"/> with the same values, bit for bit. A shard's share (<see cref="Where"/>) holds the
    /// numbers of its views (4 bytes each). Read-only; safe to read from several threads.
    /// </summary>
    public sealed class PlannedViewList : IReadOnlyList<PlannedView>, IList<PlannedView>
    {
        readonly PlanSplitViews[] _splits;
        readonly int _from;     // the first view number, when _numbers is null
        readonly int[] _numbers; // the view numbers (ascending) of a subset, or null for a range
        readonly int _count;

        internal PlannedViewList(PlanSplitViews[] splits)
        {
            _splits = splits;
            foreach (var s in splits) _count += s.Count;
        }

        PlannedViewList(PlanSplitViews[] splits, int from, int count, int[] numbers)
        {
            _splits = splits;
            _from = from;
            _count = count;
            _numbers = numbers;
        }

        public int Count => _count;

        public PlannedView this[int index]
        {
            get
            {
                if ((uint)index >= (uint)_count) throw new ArgumentOutOfRangeException(nameof(index), index, "The list has " + _count + " views.");
                return ViewNumber(_numbers != null ? _numbers[index] : _from + index);
            }
        }

        /// <summary>The views of one split, in order (no list of its own is made).</summary>
        public PlannedViewList OfSplit(DatasetSplit split)
        {
            var s = _splits[(int)split];
            if (_numbers == null)
            {
                var from = Math.Max(_from, s.Offset);
                var to = Math.Min(_from + _count, s.Offset + s.Count);
                return new PlannedViewList(_splits, from, Math.Max(0, to - from), null);
            }
            var first = LowerBound(_numbers, s.Offset);
            var end = LowerBound(_numbers, s.Offset + s.Count);
            var numbers = new int[end - first];
            Array.Copy(_numbers, first, numbers, 0, numbers.Length);
            return new PlannedViewList(_splits, 0, numbers.Length, numbers);
        }

        /// <summary>The views <paramref name="keep"/> accepts, in the same order: a list of their numbers, each view made again when read.</summary>
        public PlannedViewList Where(Func<PlannedView, bool> keep)
        {
            if (keep == null) throw new ArgumentNullException(nameof(keep));
            var numbers = new List<int>();
            for (var i = 0; i < _count; i++)
            {
                var number = _numbers != null ? _numbers[i] : _from + i;
                if (keep(ViewNumber(number))) numbers.Add(number);
            }
            return new PlannedViewList(_splits, 0, numbers.Count, numbers.ToArray());
        }

        public IEnumerator<PlannedView> GetEnumerator()
        {
            for (var i = 0; i < _count; i++) yield return this[i];
        }

        IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

        PlannedView ViewNumber(int number)
        {
            // Three splits: a linear search is the fastest.
            for (var k = 0; k < _splits.Length; k++)
            {
                var s = _splits[k];
                if (number < s.Offset + s.Count) return s.At(number - s.Offset);
            }
            throw new ArgumentOutOfRangeException(nameof(number));
        }

        static int LowerBound(int[] sorted, int value)
        {
            int lo = 0, hi = sorted.Length;
            while (lo < hi)
            {
                var mid = (lo + hi) >> 1;
                if (sorted[mid] < value) lo = mid + 1;
                else hi = mid;
            }
            return lo;
        }

        // IList<T>, read-only: lets LINQ's Count(), ToList() and ToArray() take their fast paths instead of enumerating.
        bool ICollection<PlannedView>.IsReadOnly => true;
        PlannedView IList<PlannedView>.this[int index] { get => this[index]; set => throw ReadOnly(); }
        // Views are made on demand, so two reads of one view are two objects: a view is found by its split and index.
        int IList<PlannedView>.IndexOf(PlannedView item)
        {
            if (item == null) return -1;
            for (var i = 0; i < _count; i++)
            {
                var v = this[i];
                if (v.Split == item.Split && v.Index == item.Index) return i;
            }
            return -1;
        }
        bool ICollection<PlannedView>.Contains(PlannedView item) => ((IList<PlannedView>)this).IndexOf(item) >= 0;
        void ICollection<PlannedView>.CopyTo(PlannedView[] array, int arrayIndex)
        {
            if (array == null) throw new ArgumentNullException(nameof(array));
            for (var i = 0; i < _count; i++) array[arrayIndex + i] = this[i];
        }
        void IList<PlannedView>.Insert(int index, PlannedView item) => throw ReadOnly();
        void IList<PlannedView>.RemoveAt(int index) => throw ReadOnly();
        void ICollection<PlannedView>.Add(PlannedView item) => throw ReadOnly();
        void ICollection<PlannedView>.Clear() => throw ReadOnly();
        bool ICollection<PlannedView>.Remove(PlannedView item) => throw ReadOnly();
        static NotSupportedException ReadOnly() => new NotSupportedException("A plan's views are read-only.");
    }
}
