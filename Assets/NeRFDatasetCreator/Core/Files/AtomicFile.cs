using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes a report (check <c>--json</c>, evaluate's metrics.json and report.html) so that a kill never leaves it
    /// half-written under its name: the bytes go into a temporary file beside it, <c>.&lt;name&gt;.writing-&lt;host&gt;-&lt;pid&gt;-&lt;start&gt;~</c>,
    /// which is renamed to the name only when complete (a rename within one folder is atomic, and never replaces an
    /// existing file). The temporary name records the run that writes it (<see cref="OperationOwner"/>: machine, process,
    /// its start time), so a later run removes the temporary file of a run that has provably ended — its own leftover —
    /// and leaves any other file alone, however it is named.
    /// </summary>
    public static class AtomicFile
    {
        const string Marker = ".writing-";

        /// <summary>
        /// Writes <paramref name="path"/>, which must not exist (an <see cref="IOException"/> naming it otherwise; nothing
        /// is replaced), as <paramref name="write"/> streams it. The leftovers of ended runs writing the same name are
        /// removed first (<see cref="RemoveLeftovers"/>).
        /// </summary>
        public static void WriteNew(string path, Action<Stream> write)
        {
            path = Path.GetFullPath(path);
            RemoveLeftovers(path);
            if (File.Exists(path) || Directory.Exists(path)) throw new IOException(path + " already exists; it is never replaced.");
            ThroughTemp(path, temp =>
            {
                FileOps.WriteNew(temp, write);
                FileOps.MoveFile(temp, path); // fails, replacing nothing, if path appeared meanwhile
            });
        }

        /// <summary><see cref="WriteNew(string, Action{Stream})"/> for UTF-8 text without a byte-order mark.</summary>
        public static void WriteNewText(string path, string text)
        {
            var bytes = new UTF8Encoding(false).GetBytes(text);
            WriteNew(path, stream => stream.Write(bytes, 0, bytes.Length));
        }

        /// <summary>
        /// Writes <paramref name="path"/> as UTF-8 text, replacing the file there in one rename (<see cref="File.Replace(string, string, string)"/>):
        /// for a file the product provably owns under a fixed name (the self-check's <c>check_report.json</c> inside a
        /// dataset it captured), which a rerun rewrites. A reader sees the old file or the new one, never half of either.
        /// </summary>
        public static void ReplaceText(string path, string text)
        {
            path = Path.GetFullPath(path);
            if (!File.Exists(path))
            {
                WriteNewText(path, text);
                return;
            }
            RemoveLeftovers(path);
            ThroughTemp(path, temp =>
            {
                FileOps.WriteText(temp, text);
                File.Replace(temp, path, null);
            });
        }

        /// <summary>
        /// Runs <paramref name="writeAndCommit"/> with this run's temporary file of <paramref name="path"/>, registered as
        /// live meanwhile (a run in this process never takes it for a leftover); the temporary file is removed if it fails.
        /// </summary>
        static void ThroughTemp(string path, Action<string> writeAndCommit)
        {
            var temp = TempPath(path, OperationOwner.Current);
            OperationOwner.Register(temp);
            try
            {
                if (File.Exists(temp)) FileOps.DeleteFile(temp); // this process's own, from an attempt that failed
                writeAndCommit(temp);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                if (File.Exists(temp)) File.Delete(temp);
                throw;
            }
            finally
            {
                OperationOwner.Release(temp);
            }
        }

        /// <summary>The temporary file <paramref name="owner"/> writes <paramref name="path"/> through.</summary>
        public static string TempPath(string path, OperationOwner owner) =>
            Path.Combine(Path.GetDirectoryName(path) ?? ".", "." + Path.GetFileName(path) + Marker + owner.NameTag + "~");

        /// <summary>
        /// The run that wrote <paramref name="candidate"/>, when it is exactly a temporary file of <paramref name="path"/>
        /// as <see cref="TempPath"/> names them; null for any other name (a user's file is never taken for ours).
        /// </summary>
        public static OperationOwner OwnerOf(string candidate, string path) =>
            OperationOwner.FromNameTag(Regex.Match(Path.GetFileName(candidate),
                @"^\." + Regex.Escape(Path.GetFileName(path)) + Regex.Escape(Marker) + OperationOwner.NameTagPattern + @"~\z", RegexOptions.CultureInvariant));

        /// <summary>
        /// Removes the temporary files of <paramref name="path"/> whose run has provably ended (<see cref="OperationOwner.WhyMayBeRunning"/>);
        /// returns them. A live run's, and every file not named exactly as <see cref="TempPath"/> names them, stay.
        /// </summary>
        public static IReadOnlyList<string> RemoveLeftovers(string path)
        {
            var removed = new List<string>();
            var folder = Path.GetDirectoryName(Path.GetFullPath(path));
            if (folder == null || !Directory.Exists(folder)) return removed;
            foreach (var file in Directory.GetFiles(folder, "." + Path.GetFileName(path) + Marker + "*"))
            {
                var owner = OwnerOf(file, path);
                if (owner == null || PathSafety.IsLink(file) || OperationOwner.WhyMayBeRunning(owner, file) != null) continue;
                FileOps.DeleteFile(file);
                removed.Add(file);
            }
            return removed;
        }

        /// <summary>True when <paramref name="name"/> is exactly a temporary file name of <paramref name="finalName"/> (for folders that allow only known names).</summary>
        public static bool IsTempName(string name, string finalName) => OwnerOf(name, finalName) != null;
    }
}
