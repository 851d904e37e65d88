using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>A frame's <c>relit_paths</c> as read (<see cref="RelightingKeys.Read"/>): each lighting key and the path written for it.</summary>
    public sealed class FrameRelit
    {
        static readonly IReadOnlyList<KeyValuePair<string, string>> NoPaths = new KeyValuePair<string, string>[0];

        /// <summary>(key, path as written), in the file's order; empty without the key.</summary>
        public IReadOnlyList<KeyValuePair<string, string>> Paths { get; internal set; } = NoPaths;

        /// <summary>Why the key (or one of its entries) is unusable; null when it is fine or absent.</summary>
        public string Problem { get; internal set; }

        /// <summary>Whether the frame has <c>relit_paths</c>.</summary>
        public bool Recorded => Paths.Count > 0 || Problem != null;

        /// <summary>The path written for <paramref name="key"/>, or null.</summary>
        public string PathOf(string key)
        {
            foreach (var pair in Paths)
                if (pair.Key == key) return pair.Value;
            return null;
        }

        /// <summary>A frame without relighting.</summary>
        public static readonly FrameRelit None = new FrameRelit();
    }
}
