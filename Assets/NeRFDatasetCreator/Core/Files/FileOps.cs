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

        /// <summary>
        /// The largest metadata file (transforms, config, journal, COLMAP text) read whole. This plugin's largest
        /// dataset, 3 splits of 100 000 views at about 1 kB a frame, writes about 300 MB; anything beyond is refused
        /// naming the file before a byte is read, instead of running out of memory.
        /// </summary>
        public const long MaxTextBytes = 512L << 20;

        static void Step(string operation, string path) => Faults?.Before(operation, path);

        /// <summary>
        /// Runs one operation (after the fault plan's step), so that every error names its file: an
        /// <see cref="IOException"/> or <see cref="UnauthorizedAccessException"/> whose message does not hold the
        /// path (a full disk says only "No space left on device") gets it in front.
        /// </summary>
        static void Run(string operation, string path, Action action)
        {
            try
            {
                Step(operation, path);
                action();
            }
            catch (IOException e) when (!Names(e, path)) { throw new IOException(path + ": " + e.Message, e); }
            catch (UnauthorizedAccessException e) when (!Names(e, path)) { throw new UnauthorizedAccessException(path + ": " + e.Message, e); }
        }

        static bool Names(Exception e, string path) => path == null || e.Message.IndexOf(path, StringComparison.Ordinal) >= 0;

        public static void CreateDirectory(string path) => Run("create folder", path, () => Directory.CreateDirectory(path));

        /// <summary>Writes UTF-8 text without a byte-order mark, creating or truncating the file.</summary>
        public static void WriteText(string path, string text) => Run("write", path, () => File.WriteAllText(path, text, new UTF8Encoding(false)));

        /// <summary>
        /// Writes UTF-8 text without a byte-order mark, creating or truncating the file, as <paramref name="write"/>
        /// produces it: for files too large to build as one string (invariant culture, "\n" line ends).
        /// </summary>
        public static void WriteText(string path, Action<TextWriter> write) => Run("write", path, () =>
        {
            using (var file = JsonNumbers.CreateFile(path)) write(file);
        });

        /// <summary>Writes a binary file as <paramref name="write"/> streams it (creating or truncating it): for files too large to hold in memory.</summary>
        public static void WriteStream(string path, Action<Stream> write) => Run("write", path, () =>
        {
            using (var file = new FileStream(path, FileMode.Create, FileAccess.Write, FileShare.None, 1 << 16)) write(file);
        });

        /// <summary>
        /// Opens a text file to read as a stream (UTF-8, or as its byte-order mark says): for files too large to read as
        /// one string. The same <see cref="MaxTextBytes"/> cap as <see cref="ReadText"/>: a 3 GB file is refused by its size.
        /// </summary>
        public static TextReader OpenText(string path)
        {
            TextReader reader = null;
            Run("read", path, () => reader = new StreamReader(ReadableFile.OpenRead(path, MaxTextBytes), new UTF8Encoding(false), true, 1 << 16));
            return reader;
        }

        /// <summary>Writes UTF-8 text into a file that must not exist yet (never overwrites).</summary>
        public static void WriteNewText(string path, string text) => WriteNewBytes(path, new UTF8Encoding(false).GetBytes(text));

        /// <summary>Writes bytes into a file that must not exist yet (never overwrites).</summary>
        public static void WriteNewBytes(string path, byte[] bytes) => Run("write", path, () =>
        {
            using (var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write))
                file.Write(bytes, 0, bytes.Length);
        });

        /// <summary>Writes a file that must not exist yet (never overwrites) as <paramref name="write"/> streams it: for files too large to build in memory.</summary>
        public static void WriteNew(string path, Action<Stream> write) => Run("write", path, () =>
        {
            using (var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16))
                write(file);
        });

        /// <summary>Reads a whole text file; one larger than <see cref="MaxTextBytes"/> is refused (<see cref="FileTooLargeException"/>) before it is read.</summary>
        public static string ReadText(string path)
        {
            string text = null;
            Run("read", path, () =>
            {
                // Regular files only, sized before they are opened: see ReadableFile (a FIFO would hang, /dev/zero never end).
                text = ReadableFile.ReadAllText(path, MaxTextBytes);
            });
            return text;
        }

        /// <summary>Copies without overwriting.</summary>
        public static void CopyFile(string from, string to) => Run("copy", to, () => File.Copy(from, to, false));

        /// <summary>
        /// Hard-links <paramref name="to"/> (which must not exist) to <paramref name="from"/> where the file system can
        /// (<see cref="HardLink"/>), else copies without overwriting; true when linked.
        /// </summary>
        public static bool LinkOrCopyFile(string from, string to)
        {
            var linked = false;
            Run("link", to, () =>
            {
                if (File.Exists(to) || Directory.Exists(to)) throw new IOException(to + " already exists.");
                linked = HardLink.TryCreate(from, to);
                if (!linked) File.Copy(from, to, false);
            });
            return linked;
        }

        /// <summary>Moves (renames) a file; the destination must not exist.</summary>
        public static void MoveFile(string from, string to) => Run("move", from, () => File.Move(from, to));

        /// <summary>Renames a folder; the destination must not exist.</summary>
        public static void MoveDirectory(string from, string to) => Run("move folder", from, () => Directory.Move(from, to));

        public static void DeleteFile(string path) => Run("delete", path, () => File.Delete(path));

        /// <summary>Deletes a folder and everything in it (one step: a test stops before it, not inside it).</summary>
        public static void DeleteDirectory(string path) => Run("delete folder", path, () => Directory.Delete(path, true));
    }
}
