using System.Globalization;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A file larger than what the reader will hold in memory, refused by its size on disk before anything is read or
    /// allocated. An <see cref="IOException"/>, so every caller that reports unreadable files reports this one too,
    /// naming it (a 3 GB "transforms" file used to end in "ran out of memory" naming nothing).
    /// </summary>
    public sealed class FileTooLargeException : IOException
    {
        public FileTooLargeException(string path, long length, long limit)
            : base(path + " " + Describe(length, limit))
        {
            Reason = Describe(length, limit);
            FilePath = path;
            Length = length;
        }

        public string FilePath { get; }

        /// <summary>The message without the path: "is 3 GiB, more than …".</summary>
        public string Reason { get; }

        static string Describe(long length, long limit) =>
            "is " + Size(length) + ", more than the " + Size(limit) + " read whole for a file of this kind (this plugin's largest are a few hundred MB), so it is refused unread.";
        public long Length { get; }

        /// <summary>Throws when the file at <paramref name="path"/> holds more than <paramref name="limit"/> bytes.</summary>
        public static void ThrowIfLarger(string path, long limit)
        {
            var length = new FileInfo(path).Length;
            if (length > limit) throw new FileTooLargeException(path, length, limit);
        }

        /// <summary>"3 GiB", "512 MiB", "1.5 GiB": binary units, invariant culture.</summary>
        public static string Size(long bytes)
        {
            if (bytes >= 1L << 30) return Round(bytes / (double)(1L << 30)) + " GiB";
            if (bytes >= 1L << 20) return Round(bytes / (double)(1L << 20)) + " MiB";
            return bytes.ToString(CultureInfo.InvariantCulture) + " bytes";
        }

        static string Round(double value) => System.Math.Round(value, 1).ToString("0.#", CultureInfo.InvariantCulture);
    }
}
