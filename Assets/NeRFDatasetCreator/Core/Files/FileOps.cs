using System;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The file operations of every multi-step operation (write session, merge, convert, recovery, clean) and the
    /// reads of a dataset's metadata, in one place so that a test can fail or stop the N-th of them
    /// (<see cref="Faults"/>) and prove that the next run recovers. Without a fault plan each is the plain
    /// <see cref="File"/> / <see cref="Directory"/> call.
    /// </summary>
    public static class FileOps
    {
        /// <summary>A test's fault plan; null (the default) in every real run.</summary>
        public static FileFaultPlan Faults;

        static void Step(string operation, string path) => Faults?.Before(operation, path);

        public static void CreateDirectory(string path)
        {
            Step("create folder", path);
            Directory.CreateDirectory(path);
        }

        /// <summary>Writes UTF-8 text without a byte-order mark, creating or truncating the file.</summary>
        public static void WriteText(string path, string text)
        {
            Step("write", path);
            File.WriteAllText(path, text, new UTF8Encoding(false));
        }

        /// <summary>
        /// Writes UTF-8 text without a byte-order mark, creating or truncating the file, as <paramref name="write"/>
        /// produces it: for files too large to build as one string (invariant culture, "\n" line ends).
        /// </summary>
        public static void WriteText(string path, Action<TextWriter> write)
        {
            Step("write", path);
            using (var file = JsonNumbers.CreateFile(path)) write(file);
        }

        /// <summary>Writes UTF-8 text into a file that must not exist yet (never overwrites).</summary>
        public static void WriteNewText(string path, string text) => WriteNewBytes(path, new UTF8Encoding(false).GetBytes(text));

        /// <summary>Writes bytes into a file that must not exist yet (never overwrites).</summary>
        public static void WriteNewBytes(string path, byte[] bytes)
        {
            Step("write", path);
            using (var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write))
                file.Write(bytes, 0, bytes.Length);
        }

        /// <summary>Writes a file that must not exist yet (never overwrites) as <paramref name="write"/> streams it: for files too large to build in memory.</summary>
        public static void WriteNew(string path, Action<Stream> write)
        {
            Step("write", path);
            using (var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16))
                write(file);
        }

        public static string ReadText(string path)
        {
            Step("read", path);
            return File.ReadAllText(path);
        }

        /// <summary>Copies without overwriting.</summary>
        public static void CopyFile(string from, string to)
        {
            Step("copy", to);
            File.Copy(from, to, false);
        }

        /// <summary>Moves (renames) a file; the destination must not exist.</summary>
        public static void MoveFile(string from, string to)
        {
            Step("move", from);
            File.Move(from, to);
        }

        /// <summary>Renames a folder; the destination must not exist.</summary>
        public static void MoveDirectory(string from, string to)
        {
            Step("move folder", from);
            Directory.Move(from, to);
        }

        public static void DeleteFile(string path)
        {
            Step("delete", path);
            File.Delete(path);
        }

        /// <summary>Deletes a folder and everything in it (one step: a test stops before it, not inside it).</summary>
        public static void DeleteDirectory(string path)
        {
            Step("delete folder", path);
            Directory.Delete(path, true);
        }
    }
}
