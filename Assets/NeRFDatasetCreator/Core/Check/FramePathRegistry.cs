using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>file_path</c>s a dataset's frames have named so far, to find two frames of one image (validate): the
    /// first frame of each path. A frame that names its own place — frame i of <c>transforms_train.json</c> naming
    /// <c>./train/r_i</c>, as every frame this plugin writes does — costs one bit; any other path is kept whole. So a
    /// 300 000-view dataset of ours costs 37 kB here rather than a dictionary of 300 000 strings. Paths compare as
    /// before: <see cref="ExportPaths.Normalise"/>d, ignoring case (ordinal).
    /// </summary>
    sealed class FramePathRegistry
    {
        readonly Dictionary<string, (string file, int index)> _others = new Dictionary<string, (string file, int index)>(StringComparer.OrdinalIgnoreCase);
        readonly List<ulong>[] _ownPlace = { new List<ulong>(), new List<ulong>(), new List<ulong>() };
        readonly List<string> _added = new List<string>();
        DatasetSplit _reading;

        /// <summary>Starts a transforms file; <see cref="ForgetFile"/> undoes what its frames add.</summary>
        public void BeginFile(DatasetSplit split)
        {
            _reading = split;
            _added.Clear();
        }

        /// <summary>Undoes what the frames of the file begun last added (the file turned out to be malformed).</summary>
        public void ForgetFile()
        {
            foreach (var key in _added) _others.Remove(key);
            _added.Clear();
            _ownPlace[(int)_reading].Clear();
        }

        /// <summary>
        /// Records frame <paramref name="index"/> of <paramref name="file"/> (the split's file begun last) naming
        /// <paramref name="key"/> (normalised); false, with the frame that named it first, when an earlier frame did.
        /// </summary>
        public bool Add(string key, string file, int index, out (string file, int index) first)
        {
            var canonical = TryParse(key, out var split, out var number);
            if (canonical && IsSet(split, number))
            {
                first = (DatasetLayout.TransformsFileName(split), number);
                return false;
            }
            if (_others.TryGetValue(key, out first)) return false;
            if (canonical && split == _reading && number == index) Set(split, number);
            else
            {
                _others[key] = (file, index);
                _added.Add(key);
            }
            return true;
        }

        bool IsSet(DatasetSplit split, int i)
        {
            var words = _ownPlace[(int)split];
            var w = i >> 6;
            return w < words.Count && (words[w] & (1UL << (i & 63))) != 0;
        }

        void Set(DatasetSplit split, int i)
        {
            var words = _ownPlace[(int)split];
            var w = i >> 6;
            while (words.Count <= w) words.Add(0);
            words[w] |= 1UL << (i & 63);
        }

        /// <summary>
        /// Whether <paramref name="key"/> is <c>&lt;split&gt;/r_&lt;i&gt;</c> — the path of view i of a split, compared
        /// ignoring case as the dictionary does, with i written as <see cref="DatasetLayout.Stem"/> writes it (no leading zeros).
        /// </summary>
        static bool TryParse(string key, out DatasetSplit split, out int number)
        {
            split = default;
            number = 0;
            foreach (var s in DatasetSplits.All)
            {
                var name = DatasetSplits.Name(s);
                var prefix = name.Length + 3; // "<split>/r_"
                if (key.Length <= prefix || key.Length > prefix + 9) continue;
                if (string.Compare(key, 0, name + "/r_", 0, prefix, StringComparison.OrdinalIgnoreCase) != 0) continue;
                if (key[prefix] == '0' && key.Length > prefix + 1) return false;
                for (var k = prefix; k < key.Length; k++)
                {
                    var c = key[k];
                    if (c < '0' || c > '9') return false;
                    number = number * 10 + (c - '0');
                }
                split = s;
                return true;
            }
            return false;
        }
    }
}
