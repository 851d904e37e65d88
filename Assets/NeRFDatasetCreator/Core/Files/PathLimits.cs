using System;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The file system's limits on names and paths, checked before an operation starts: an output whose name is legal
    /// can still be refused by the OS once a working folder's suffix (<see cref="WorkingFolders.LongestSuffix"/>) or the
    /// files inside are added, which would otherwise fail half-way with <see cref="PathTooLongException"/>.
    /// </summary>
    public static class PathLimits
    {
        /// <summary>Bytes in one name (Linux NAME_MAX, counted in UTF-8; NTFS and APFS allow 255 UTF-16 units, never fewer).</summary>
        public const int MaxNameBytes = 255;

        /// <summary>The longest dataset-relative path a run writes inside its folder, e.g. <c>train/r_9999999_normal_0000.png</c>.</summary>
        public const int LongestInside = 40;

        /// <summary>Characters in a whole path: Windows' MAX_PATH (Mono in Unity honours it), macOS' PATH_MAX, Linux's PATH_MAX.</summary>
        public static int MaxPath =>
            RuntimeInformation.IsOSPlatform(OSPlatform.Windows) ? 259 :
            RuntimeInformation.IsOSPlatform(OSPlatform.OSX) ? 1023 : 4095;

        /// <summary>
        /// Null when <paramref name="fullPath"/> with a working-folder suffix of <paramref name="suffix"/> characters and
        /// files <see cref="LongestInside"/> deep stays within the limits; otherwise the problem, naming <paramref name="field"/>.
        /// </summary>
        public static ValidationProblem Check(string fullPath, string field, int suffix = WorkingFolders.LongestSuffix)
        {
            var name = Path.GetFileName(fullPath.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar));
            var nameBytes = Encoding.UTF8.GetByteCount(name);
            if (nameBytes + suffix > MaxNameBytes)
                return new ValidationProblem(field == "outputFolder" ? "name" : field, name,
                    "is " + nameBytes + " bytes long; with the working folder's suffix (" + suffix + " more) the name would exceed the file system's " + MaxNameBytes + ".",
                    "Use a name of at most " + (MaxNameBytes - suffix) + " bytes.");
            var longest = fullPath.Length + suffix + 1 + LongestInside;
            if (longest > MaxPath)
                return new ValidationProblem(field, fullPath,
                    "is " + fullPath.Length + " characters long; the files written inside it (plus the working folder's suffix) would reach " + longest +
                    ", beyond this system's limit of " + MaxPath + ".",
                    "Choose a folder with a path of at most " + (MaxPath - suffix - 1 - LongestInside) + " characters.");
            return null;
        }
    }
}
