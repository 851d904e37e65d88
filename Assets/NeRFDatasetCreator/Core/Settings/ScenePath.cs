using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a config's <c>"scene"</c> is. A path that starts with <c>Assets/</c> or <c>Packages/</c> is Unity's
    /// project-relative asset path, as the window saves it. Any other relative path is relative to the folder of the
    /// config file, so a config shipped beside its scene keeps working wherever it is copied: Package Manager imports
    /// the sample to <c>Assets/Samples/&lt;package display name&gt;/&lt;version&gt;/&lt;sample name&gt;/</c>
    /// (UnityCsReference, Modules/PackageManagerUI/Editor/Services/Packages/PackageSample.cs, <c>Sample.importPath</c>),
    /// not to the development project's <c>Assets/Samples/NeRFSample/</c>, and the sample's configs say
    /// <c>"scene": "NeRFSample.unity"</c>.
    /// </summary>
    public static class ScenePath
    {
        /// <summary>
        /// The scene as the project-relative path <c>EditorSceneManager.OpenScene</c> takes (forward slashes), "" when
        /// the config names none, or null when the path leads outside the project folder.
        /// </summary>
        public static string Resolve(string scene, string configFile, string projectRoot)
        {
            if (string.IsNullOrWhiteSpace(scene)) return "";
            var normalised = scene.Trim().Replace('\\', '/');
            if (IsProjectRelative(normalised)) return normalised;
            var root = Path.GetFullPath(projectRoot);
            var full = Path.IsPathRooted(normalised)
                ? Path.GetFullPath(normalised)
                : Path.GetFullPath(Path.Combine(Path.GetDirectoryName(Path.GetFullPath(configFile)) ?? root, normalised));
            var relative = Path.GetRelativePath(root, full).Replace('\\', '/');
            if (relative == ".." || relative.StartsWith("../", StringComparison.Ordinal) || Path.IsPathRooted(relative)) return null;
            return relative;
        }

        static bool IsProjectRelative(string path) =>
            path.StartsWith("Assets/", StringComparison.Ordinal) || path.StartsWith("Packages/", StringComparison.Ordinal);
    }
}
