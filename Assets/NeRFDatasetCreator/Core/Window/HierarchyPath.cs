using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A scene object's hierarchy path, "Root/Child/Target", as stored in <see cref="DatasetSettings.Target"/> and
    /// <see cref="CameraSettings.CopyFromCamera"/>: a scene object reference cannot survive in a settings file across
    /// editor sessions (it is an instance ID), but its path can, and batch mode finds objects by the same path.
    /// </summary>
    public static class HierarchyPath
    {
        public const char Separator = '/';

        /// <summary>The path of names from the scene root down to the object.</summary>
        public static string Join(IEnumerable<string> namesFromRoot)
        {
            if (namesFromRoot == null) throw new ArgumentNullException(nameof(namesFromRoot));
            return string.Join(Separator.ToString(), namesFromRoot);
        }

        /// <summary>The names of a path, root first; a leading '/' (as some tools write) is ignored.</summary>
        public static IReadOnlyList<string> Split(string path)
        {
            if (string.IsNullOrEmpty(path)) return Array.Empty<string>();
            var trimmed = path[0] == Separator ? path.Substring(1) : path;
            return trimmed.Length == 0 ? Array.Empty<string>() : trimmed.Split(Separator);
        }

        /// <summary>
        /// A warning when the path cannot find the object again: a name containing '/' splits into two names.
        /// Null when the path is exact.
        /// </summary>
        public static ValidationProblem CheckNames(string field, IEnumerable<string> namesFromRoot)
        {
            var names = namesFromRoot?.ToList() ?? new List<string>();
            var bad = names.FirstOrDefault(n => n != null && n.IndexOf(Separator) >= 0);
            if (bad == null) return null;
            return new ValidationProblem(field, "\"" + bad + "\"", "contains '/', so its hierarchy path cannot find it again after Unity restarts or in batch mode.",
                "Rename the object without '/'.");
        }
    }
}
