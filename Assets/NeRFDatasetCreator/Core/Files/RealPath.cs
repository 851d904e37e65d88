using System;
using System.IO;
using System.Runtime.InteropServices;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a path really leads once every symbolic link on its existing part is followed — what the "never inside the
    /// dataset" tests of the commands that write compare (<see cref="Inside"/>), so that a link (<c>--out link</c> with
    /// <c>link → dataset/</c>) cannot carry a write into the dataset. .NET Standard 2.1 cannot read a link's target
    /// (<c>FileSystemInfo.LinkTarget</c> is .NET 6), so on Linux and macOS each existing component is resolved by
    /// POSIX <c>realpath(3)</c>. On Windows links are not resolved (the comparison stays lexical, as before): reparse
    /// points there include OneDrive's placeholders, and refusing those would refuse ordinary folders.
    /// </summary>
    public static class RealPath
    {
        /// <summary>
        /// The absolute path <paramref name="path"/> leads to: its existing components with every link followed (".."
        /// taken physically, as the OS does), the rest appended as written. Null, with <paramref name="reason"/>, when a
        /// link on the way cannot be resolved (its target is missing, or a loop).
        /// </summary>
        public static string Of(string path, out string reason)
        {
            reason = null;
            var absolute = Path.IsPathRooted(path) ? path : Path.Combine(Directory.GetCurrentDirectory(), path);
            var root = Path.GetPathRoot(absolute);
            var current = root;
            var exists = true;
            foreach (var part in absolute.Substring(root.Length).Split(new[] { Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar }, StringSplitOptions.RemoveEmptyEntries))
            {
                if (part == ".") continue;
                if (part == "..")
                {
                    // current is real (or below a missing folder, which holds no link): its parent is the physical one.
                    // The root's parent is the root (Mono's GetDirectoryName throws on "", so it is never asked).
                    if (current.Length > root.Length) current = Path.GetDirectoryName(current.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar)) ?? root;
                    continue;
                }
                var next = Path.Combine(current, part);
                // Windows: reparse points include OneDrive's placeholders, which are no links; they are kept as written
                // (the comparison there is the lexical one it always was).
                if (exists && !Windows && PathSafety.IsLink(next))
                {
                    var resolved = Resolve(next);
                    if (resolved == null)
                    {
                        reason = "goes through the symbolic link " + next + ", whose target does not exist (or is a loop of links)";
                        return null;
                    }
                    current = resolved;
                    continue;
                }
                if (exists && !File.Exists(next) && !Directory.Exists(next)) exists = false;
                current = next;
            }
            return current.Length > root.Length ? current.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar) : current;
        }

        /// <summary>
        /// True when <paramref name="path"/> really lies in <paramref name="folder"/> (or is it), both with their links
        /// followed; also true when either cannot be resolved (a caller that refuses on true never writes through an
        /// unresolved link).
        /// </summary>
        public static bool Inside(string path, string folder)
        {
            var real = Of(path, out _);
            var realFolder = Of(folder, out _);
            if (real == null || realFolder == null) return true;
            var prefix = realFolder.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar) + Path.DirectorySeparatorChar;
            return string.Equals(real, realFolder.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar), StringComparison.Ordinal) ||
                   (real + Path.DirectorySeparatorChar).StartsWith(prefix, StringComparison.Ordinal);
        }

        static readonly bool Windows = RuntimeInformation.IsOSPlatform(OSPlatform.Windows);

        static string Resolve(string link)
        {
            try
            {
                var resolved = realpath(link, IntPtr.Zero);
                if (resolved == IntPtr.Zero) return null; // a dangling link (ENOENT) or a loop (ELOOP)
                try
                {
                    var text = Utf8(resolved);
                    return text.Length > 0 ? text : null;
                }
                finally
                {
                    free(resolved);
                }
            }
            catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException)
            {
                return null;
            }
        }

        /// <summary>The NUL-terminated UTF-8 string at <paramref name="p"/> (Marshal.PtrToStringUTF8 is not in .NET Standard 2.1).</summary>
        static string Utf8(IntPtr p)
        {
            var length = 0;
            while (Marshal.ReadByte(p, length) != 0) length++;
            var bytes = new byte[length];
            Marshal.Copy(p, bytes, 0, length);
            return System.Text.Encoding.UTF8.GetString(bytes);
        }

        // POSIX realpath(3) with a null buffer allocates the result (free it with free(3)); libc is mapped to the C
        // library on Linux and macOS by .NET and by Mono (Unity).
        [DllImport("libc", CharSet = CharSet.Ansi)]
        static extern IntPtr realpath(string path, IntPtr resolved);

        [DllImport("libc")]
        static extern void free(IntPtr pointer);
    }
}
