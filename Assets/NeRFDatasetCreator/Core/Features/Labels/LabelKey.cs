using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// An object's identity across captures: its hierarchy path as sibling indices and names, e.g.
    /// <c>0:Street/3:Car</c>. Unity's instance IDs change from session to session; this does not while the scene is
    /// unchanged, so a re-capture, another shard or another time step finds the same object under the same key.
    /// </summary>
    public static class LabelKey
    {
        public static string Of(IReadOnlyList<int> siblingPath, string path)
        {
            var names = (path ?? "").Split('/');
            var text = new StringBuilder();
            for (var i = 0; i < siblingPath.Count; i++)
            {
                if (i > 0) text.Append('/');
                text.Append(siblingPath[i].ToString(CultureInfo.InvariantCulture)).Append(':');
                if (i < names.Length) text.Append(names[i]);
            }
            return text.ToString();
        }

        /// <summary>
        /// The ids' order: sibling paths compared index by index (a parent before its children, the hierarchy window's
        /// order), then names (several loaded scenes may repeat a root's index) ordinally.
        /// </summary>
        public static int Compare(IReadOnlyList<int> aSiblings, string aPath, IReadOnlyList<int> bSiblings, string bPath)
        {
            var n = System.Math.Min(aSiblings.Count, bSiblings.Count);
            for (var i = 0; i < n; i++)
                if (aSiblings[i] != bSiblings[i]) return aSiblings[i].CompareTo(bSiblings[i]);
            if (aSiblings.Count != bSiblings.Count) return aSiblings.Count.CompareTo(bSiblings.Count);
            return string.CompareOrdinal(aPath, bPath);
        }
    }
}
