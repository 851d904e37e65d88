using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a dataset may be written. The default is <c>&lt;project&gt;/NeRFDatasets/&lt;name&gt;</c>, outside
    /// <c>Assets/</c>, so Unity never imports the images (the original plugin stalled the editor creating .meta
    /// files). A folder inside <c>Assets/</c> is refused unless a path component below <c>Assets</c> ends in
    /// <c>~</c>, which Unity ignores. A folder inside another dataset, or one that holds other files, is refused;
    /// an existing dataset is refused unless the overwrite policy is <see cref="OverwritePolicy.Replace"/> and it is
    /// provably this plugin's, holds no export and — for a plan, which renders nothing — no rendered images
    /// (<see cref="OwnDataset.WhyNotReplaceable"/>). A path too long once the working folder's suffix is added
    /// (<see cref="PathLimits"/>) and a mount point (<see cref="MountPoints"/>) are refused up front.
    /// </summary>
    public static class SafeOutput
    {
        /// <summary>The default parent folder of datasets, at the project root (next to Assets/).</summary>
        public const string DefaultParentFolder = "NeRFDatasets";

        /// <summary>
        /// The dataset folder for these settings: <c>OutputFolder/Name</c>, where an empty OutputFolder means
        /// <c>&lt;project&gt;/NeRFDatasets</c> and a relative one is relative to the project root.
        /// </summary>
        public static string ResolveOutputFolder(DatasetSettings settings, string projectRoot)
        {
            var root = string.IsNullOrEmpty(projectRoot) ? Directory.GetCurrentDirectory() : projectRoot;
            var parent = string.IsNullOrWhiteSpace(settings.OutputFolder) ? DefaultParentFolder : settings.OutputFolder;
            return Path.GetFullPath(Path.Combine(root, parent, settings.Name ?? ""));
        }

        /// <summary>True when <paramref name="folder"/> holds a Blender-format dataset (a transforms file or our config).</summary>
        public static bool LooksLikeDataset(string folder) =>
            Directory.Exists(folder) &&
            (File.Exists(Path.Combine(folder, DatasetLayout.ConfigFileName)) ||
             DatasetSplits.All.Any(s => File.Exists(Path.Combine(folder, DatasetLayout.TransformsFileName(s)))));

        /// <summary>
        /// Every reason not to write a dataset into <paramref name="datasetFolder"/>. With no
        /// <paramref name="projectRoot"/>, a Unity project is recognised by an <c>Assets</c> folder next to
        /// <c>ProjectSettings</c>. <paramref name="field"/> is what the user gave the folder as: the config's
        /// <c>outputFolder</c>, or a command line's <c>--out</c>.
        /// </summary>
        /// <param name="rendersImages">False for a run that writes no images (<c>nerf-dataset plan</c>): it may never replace a rendered dataset.</param>
        public static IReadOnlyList<ValidationProblem> CheckOutputFolder(string datasetFolder, string projectRoot, OverwritePolicy policy,
            string field = "outputFolder", bool rendersImages = true)
        {
            var problems = new List<ValidationProblem>();
            string full;
            try
            {
                full = Path.GetFullPath(datasetFolder);
            }
            catch (Exception e) when (e is ArgumentException || e is NotSupportedException || e is PathTooLongException)
            {
                problems.Add(new ValidationProblem(field, datasetFolder ?? "", "is not a valid path: " + e.Message, "Choose another folder."));
                return problems;
            }
            var shown = full;
            var length = PathLimits.Check(full, field);
            if (length != null)
            {
                problems.Add(length);
                return problems;
            }
            var mount = MountPoints.Check(full, field);
            if (mount != null) problems.Add(mount);

            var assets = InsideUnityAssets(full, projectRoot);
            if (assets != null)
                problems.Add(new ValidationProblem(field, shown,
                    "is inside the Unity project's Assets folder, so Unity would import every image (slow, and it creates a .meta per file).",
                    "Use the default <project>/" + DefaultParentFolder + "/, any folder outside Assets, or a folder whose name ends in '~' (e.g. Assets/Datasets~/), which Unity ignores."));

            var inside = WhyInsideDataset(full, null);
            if (inside != null)
                problems.Add(new ValidationProblem(field, shown, inside + "; loaders would see a mixture.", "Choose a folder outside any dataset."));

            if (File.Exists(full))
                problems.Add(new ValidationProblem(field, shown, "is an existing file, not a folder.", "Choose another dataset name or folder."));
            else if (Directory.Exists(full) && Directory.EnumerateFileSystemEntries(full).Any())
            {
                if (!LooksLikeDataset(full))
                    problems.Add(new ValidationProblem(field, shown, "already holds files that are not a dataset; they are never overwritten.",
                        "Choose another dataset name or an empty folder."));
                else if (policy == OverwritePolicy.Never)
                    problems.Add(new ValidationProblem("overwrite", "never",
                        "forbids replacing the existing dataset " + full + ".",
                        "Choose another dataset name, or set overwrite to \"replace\" to replace it once the new one is complete."));
                else if (OwnDataset.WhyNotReplaceable(full, rendersImages) is string why)
                    problems.Add(new ValidationProblem("overwrite", "replace",
                        "would delete " + full + ", but " + why + "; replace deletes only a dataset this plugin wrote, never a file it did not write or an export, and a plan never deletes rendered images.",
                        "Choose another dataset name, or move what you want to keep out of it first."));
            }

            var writable = CheckWritable(full);
            if (writable != null) problems.Add(new ValidationProblem(field, shown, writable, "Choose a folder you can write to."));
            return problems;
        }

        /// <summary>
        /// The one "never inside the dataset" rule of every command that writes (plan and capture, evaluate, check
        /// <c>--json</c>, merge's shard warning): why writing at <paramref name="path"/> would really write into
        /// <paramref name="dataset"/> — or, when that is null, into any existing dataset above it — with every symbolic
        /// link on the way followed (<see cref="RealPath"/>); null when it would not. The clause names the dataset, and
        /// the real path when a link leads there ("is inside the existing dataset /d (through a symbolic link: it is
        /// really /d/x)"); a link that cannot be resolved is refused too.
        /// </summary>
        public static string WhyInsideDataset(string path, string dataset)
        {
            var full = Path.GetFullPath(path).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            var real = RealPath.Of(full, out var unresolved);
            if (real == null) return unresolved + ", so where it leads cannot be checked";
            var via = real == full ? "" : " (through a symbolic link: it is really " + real + ")";
            if (dataset != null)
            {
                var realDataset = RealPath.Of(dataset, out unresolved);
                if (realDataset == null) return "names the dataset " + dataset + ", which " + unresolved;
                return RealPath.Inside(real, realDataset) ? "is inside the dataset " + Path.GetFullPath(dataset).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar) + via : null;
            }
            for (var ancestor = Path.GetDirectoryName(real); ancestor != null; ancestor = Path.GetDirectoryName(ancestor))
                if (LooksLikeDataset(ancestor))
                    return "is inside the existing dataset " + ancestor + via;
            return null;
        }

        /// <summary>The Assets folder <paramref name="full"/> is imported from, or null when it is not imported.</summary>
        static string InsideUnityAssets(string full, string projectRoot)
        {
            var components = new List<string>();
            for (var dir = full; dir != null; dir = Path.GetDirectoryName(dir))
            {
                var name = Path.GetFileName(dir);
                // Any case: on Windows and macOS "assets" is Unity's Assets folder; refusing it on Linux costs nothing.
                if (string.Equals(name, "Assets", StringComparison.OrdinalIgnoreCase))
                {
                    var project = Path.GetDirectoryName(dir);
                    var isProject = !string.IsNullOrEmpty(projectRoot)
                        ? SamePath(project, projectRoot)
                        : project != null && Directory.Exists(Path.Combine(project, "ProjectSettings"));
                    if (isProject)
                        return components.Any(c => c.EndsWith("~", StringComparison.Ordinal)) ? null : dir;
                }
                components.Add(name);
            }
            return null;
        }

        static bool SamePath(string a, string b) =>
            string.Equals(Path.GetFullPath(a).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar),
                Path.GetFullPath(b).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar),
                // Case-insensitive everywhere: macOS is case-insensitive too, and erring towards "same" only refuses more.
                StringComparison.OrdinalIgnoreCase);

        /// <summary>
        /// Null when a file can be created where the dataset's parent folder is or will be; otherwise why not.
        /// Probes the nearest existing ancestor by creating and deleting an uniquely named empty file.
        /// </summary>
        static string CheckWritable(string full)
        {
            var dir = Path.GetDirectoryName(full);
            while (dir != null && !Directory.Exists(dir))
            {
                if (File.Exists(dir)) return "cannot be created: " + dir + " is a file.";
                dir = Path.GetDirectoryName(dir);
            }
            if (dir == null) return "has no existing parent folder.";
            var probe = Path.Combine(dir, ".nerf-write-probe-" + Guid.NewGuid().ToString("N") + "~");
            try
            {
                using (new FileStream(probe, FileMode.CreateNew, FileAccess.Write)) { }
                File.Delete(probe);
                return null;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return "is not writable: " + dir + " refused a new file (" + e.Message + ").";
            }
        }
    }
}
