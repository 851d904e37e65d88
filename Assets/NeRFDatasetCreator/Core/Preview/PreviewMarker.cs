using System;

namespace NerfDatasetCreator
{
    /// <summary>One planned camera as the preview shows it: which split, its index there, and where it stands.</summary>
    [Serializable]
    public readonly struct PreviewMarker
    {
        public PreviewMarker(PreviewSplit split, int index, Vector3d position)
        {
            Split = split;
            Index = index;
            Position = position;
        }

        public PreviewSplit Split { get; }

        /// <summary>The view's index within its split: the <c>i</c> of <c>./&lt;split&gt;/r_i</c>.</summary>
        public int Index { get; }

        public Vector3d Position { get; }

        /// <summary>"train r_12": how the preview labels a picked camera, named like its image file.</summary>
        public string Label => SplitColors.NameOf(Split) + " r_" + Index.ToString(System.Globalization.CultureInfo.InvariantCulture);
    }
}
