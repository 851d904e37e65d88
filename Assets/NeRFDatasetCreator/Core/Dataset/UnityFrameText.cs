using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The engine-free half of <see cref="UnityFrameFacts"/> (issue 34): how the Editor's facts about a capture's target
    /// are written — the scene path and hierarchy path as one string, a GlobalObjectId only where it identifies
    /// something, and a Unity <c>Matrix4x4</c> as 16 numbers row-major.
    /// </summary>
    public static class UnityFrameText
    {
        /// <summary>
        /// "Assets/Scenes/Lego.unity:/Root/Lego": the scene asset's path (<c>Scene.path</c>, empty for a scene never
        /// saved, which gives ":/Root/Lego"), a colon, then the hierarchy path from the scene root, each name after a '/'.
        /// </summary>
        public static string TargetPath(string sceneAssetPath, IEnumerable<string> namesFromRoot)
        {
            if (namesFromRoot == null) throw new ArgumentNullException(nameof(namesFromRoot));
            var names = namesFromRoot.ToList();
            if (names.Count == 0) throw new ArgumentException("A target has at least its own name.", nameof(namesFromRoot));
            return (sceneAssetPath ?? "") + ":/" + HierarchyPath.Join(names);
        }

        /// <summary>
        /// <paramref name="text"/> (<c>GlobalObjectId.ToString()</c>: "GlobalObjectId_V1-{type}-{asset GUID}-{object}-{prefab}",
        /// UnityCsReference Editor/Mono/GlobalObjectId.bindings.cs line 52 at 2022.3.76f1, 57 at 6000.0.78f1), or null when it
        /// identifies nothing: the null id (type 0) or an all-zero asset GUID, as an object of a scene never saved has.
        /// </summary>
        public static string GlobalObjectIdOrNull(string text)
        {
            if (string.IsNullOrEmpty(text)) return null;
            var parts = text.Split('-');
            if (parts.Length != 5 || parts[0] != "GlobalObjectId_V1") return null;
            if (parts[1] == "0") return null;
            return parts[2].Trim('0').Length == 0 ? null : text;
        }

        /// <summary>A 4×4 as 16 numbers row-major: <paramref name="element"/>(row, column), as Unity's <c>Matrix4x4[row, column]</c> reads.</summary>
        public static double[] RowMajor(Func<int, int, double> element)
        {
            if (element == null) throw new ArgumentNullException(nameof(element));
            var m = new double[16];
            for (var row = 0; row < 4; row++)
                for (var column = 0; column < 4; column++)
                    m[row * 4 + column] = element(row, column);
            return m;
        }
    }
}
