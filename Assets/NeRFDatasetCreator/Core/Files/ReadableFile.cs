using System;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The one gate every file the plugin reads passes first (transforms and configs through <see cref="FileOps.ReadText"/>,
    /// PNG, PLY, npy.gz, OBJ, labels.json, metrics.json): its size on disk is tested before it is opened, and no more
    /// than that size is ever read. What it refuses is an <see cref="IOException"/> naming the file, so every caller that
    /// reports unreadable files reports these too.
    /// <para>
    /// A FIFO must be refused without being opened (opening one waits for a writer, forever), and .NET cannot tell one
    /// from a file without opening it: <c>File.GetAttributes</c> says <c>Normal</c> for a FIFO and for <c>/dev/zero</c>
    /// as for a regular file (measured on .NET 10, Linux; ReadableFileTests pins it). What does tell them apart is the
    /// size: pipes and character devices report 0 bytes (stat's st_size), while <c>/dev/zero</c> then reads forever.
    /// So a 0-byte entry is refused unopened — an empty file is no valid PNG, PLY, npy or JSON either — and a file is
    /// read no further than the size it reported.
    /// </para>
    /// </summary>
    public static class ReadableFile
    {
        /// <summary>
        /// The largest image (PNG) read whole: an 8K × 8K 16-bit RGBA PNG that deflate could not shrink at all is 512 MiB.
        /// </summary>
        public const long MaxImageBytes = 512L << 20;

        /// <summary>The largest PLY, OBJ or npy.gz read (streamed, but each value kept): 2 GiB, beyond what a capture or trainer writes.</summary>
        public const long MaxGeometryBytes = 2L << 30;

        /// <summary>
        /// The size of the file at <paramref name="path"/>, which is about to be read: refused (an <see cref="IOException"/>
        /// naming it) when it is missing, a folder, 0 bytes (empty, or a pipe or device) or larger than <paramref name="limit"/>.
        /// </summary>
        public static long Length(string path, long limit)
        {
            var info = new FileInfo(path);
            if (Directory.Exists(path)) throw new UnreadableFileException(path, "is a folder, not a file.");
            if (!info.Exists) throw new FileNotFoundException(path + " does not exist.", path);
            var length = info.Length;
            if (length == 0) throw new UnreadableFileException(path, EmptyReason);
            if (length > limit) throw new FileTooLargeException(path, length, limit);
            return length;
        }

        /// <summary>The reason a 0-byte entry is refused.</summary>
        public const string EmptyReason = "is empty (0 bytes) or is not a regular file (a pipe or device reports no size), so it is not read.";

        /// <summary>
        /// Opens the file to read after <see cref="Length"/>'s test: the stream ends at the size the file had then, even if
        /// it grows or is a device that never ends.
        /// </summary>
        public static Stream OpenRead(string path, long limit)
        {
            var length = Length(path, limit);
            var file = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, 1 << 16, FileOptions.SequentialScan);
            return new BoundedStream(file, length);
        }

        /// <summary>The whole file, after <see cref="Length"/>'s test; a file that shrank while read is an <see cref="IOException"/>.</summary>
        public static byte[] ReadAllBytes(string path, long limit)
        {
            var length = Length(path, limit);
            var bytes = new byte[length];
            using (var file = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, 1 << 16, FileOptions.SequentialScan))
            {
                var read = 0;
                while (read < bytes.Length)
                {
                    var n = file.Read(bytes, read, bytes.Length - read);
                    if (n <= 0) throw new UnreadableFileException(path, "became shorter while it was read (" + read + " of " + length + " bytes).");
                    read += n;
                }
            }
            return bytes;
        }

        /// <summary>The whole file as text (UTF-8, or as its byte-order mark says), after <see cref="Length"/>'s test.</summary>
        public static string ReadAllText(string path, long limit)
        {
            using (var reader = new StreamReader(OpenRead(path, limit), new UTF8Encoding(false), true))
                return reader.ReadToEnd();
        }

        /// <summary>A read-only view of the first <c>length</c> bytes of a stream.</summary>
        sealed class BoundedStream : Stream
        {
            readonly Stream inner;
            long left;

            public BoundedStream(Stream inner, long length)
            {
                this.inner = inner;
                left = length;
                Length = length;
            }

            public override bool CanRead => true;
            public override bool CanSeek => false;
            public override bool CanWrite => false;
            public override long Length { get; }

            public override long Position
            {
                get => Length - left;
                set => throw new NotSupportedException();
            }

            public override int Read(byte[] buffer, int offset, int count)
            {
                if (left <= 0) return 0;
                var n = inner.Read(buffer, offset, (int)Math.Min(count, left));
                left -= n;
                return n;
            }

            public override int ReadByte()
            {
                if (left <= 0) return -1;
                var b = inner.ReadByte(); // FileStream's own buffer: header readers read byte by byte
                if (b >= 0) left--;
                return b;
            }

            public override void Flush() { }
            public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
            public override void SetLength(long value) => throw new NotSupportedException();
            public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();

            protected override void Dispose(bool disposing)
            {
                if (disposing) inner.Dispose();
                base.Dispose(disposing);
            }
        }
    }
}
