using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whether a folder is the root of a mounted file system (a disk, a network share, a container volume). A finished
    /// dataset is renamed onto its output, and no OS renames a folder onto a mount point ("Device or resource busy"),
    /// so such an output is refused up front with the folder to use instead.
    /// </summary>
    public static class MountPoints
    {
        public static bool IsMountPoint(string fullPath)
        {
            var path = fullPath.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            if (path.Length == 0 || !Directory.Exists(path)) return false;
            try
            {
                // DriveInfo lists mount points on Linux and macOS (from the mount table) and drive roots on Windows.
                return DriveInfo.GetDrives().Any(d => string.Equals(
                    d.RootDirectory.FullName.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar), path, StringComparison.Ordinal));
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is PlatformNotSupportedException)
            {
                return false;
            }
        }

        public static ValidationProblem Check(string fullPath, string field)
        {
            if (!IsMountPoint(fullPath)) return null;
            return new ValidationProblem(field, fullPath,
                "is a mount point (the root of its own file system); a finished dataset is moved into place by renaming, which a mount point refuses.",
                "Write into a folder inside it, e.g. " + Path.Combine(fullPath, "dataset") + ".");
        }
    }
}
