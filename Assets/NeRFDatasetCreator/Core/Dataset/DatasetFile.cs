using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One file a frame's key names (<c>file_path</c>, <c>depth_path</c>, …), resolved by the dataset's one path rule:
    /// relative to the dataset folder, inside it or refused (<see cref="PathSafety.Inside"/>: rooted, "..", or through a
    /// symbolic link), never guessed from another file's name. <c>file_path</c> follows the loaders: the path as
    /// written when it has an extension and that file exists, else the path + ".png" (bmild/nerf and nerfstudio's
    /// blender parser append it) unless it already ends in ".png".
    /// </summary>
    public sealed class DatasetFile
    {
        bool? _exists;

        /// <summary>The key that names it.</summary>
        public string Key { get; private set; }

        /// <summary>The value as written in the transforms file.</summary>
        public string Written { get; private set; }

        /// <summary>Relative to the dataset, forward slashes, no leading "./" (with ".png" appended for <c>file_path</c> by the rule above).</summary>
        public string Relative { get; private set; }

        /// <summary>The absolute path, or null when the path leaves the dataset.</summary>
        public string FullPath { get; private set; }

        /// <summary>Why the path is refused (<see cref="PathSafety.Inside"/>'s reason), or null when it is inside.</summary>
        public string Outside { get; private set; }

        public bool IsInside => FullPath != null;

        /// <summary>Whether the file is inside the dataset and exists (looked up once).</summary>
        public bool Exists => FullPath != null && (_exists ?? (_exists = File.Exists(FullPath)).Value);

        /// <summary>What is wrong with it, naming the key and the file: it leaves the dataset or is missing; null when it exists.</summary>
        public string Problem =>
            Outside != null ? Key + " " + Written + " leaves the dataset folder (" + Outside + ")." :
            !Exists ? Key + " " + Written + " is missing." : null;

        /// <summary>Resolves <paramref name="written"/> under <paramref name="root"/>; <paramref name="image"/> applies <c>file_path</c>'s ".png" rule.</summary>
        public static DatasetFile Resolve(string root, string key, string written, bool image)
        {
            var file = new DatasetFile { Key = key, Written = written };
            var relative = ExportPaths.Normalise(written ?? "");
            if (image)
            {
                var asWritten = Path.HasExtension(relative) ? PathSafety.Inside(root, relative, out _) : null;
                if (asWritten != null && File.Exists(asWritten))
                {
                    file.Relative = relative;
                    file.FullPath = asWritten;
                    file._exists = true;
                    return file;
                }
                if (!relative.EndsWith(".png", System.StringComparison.OrdinalIgnoreCase)) relative += ".png";
            }
            file.Relative = relative;
            file.FullPath = PathSafety.Inside(root, relative, out var outside);
            file.Outside = outside;
            return file;
        }
    }
}
