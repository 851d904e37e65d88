using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>A file refused before it is read (a folder, a pipe or device, an empty file), naming it.</summary>
    public sealed class UnreadableFileException : IOException
    {
        public UnreadableFileException(string path, string reason) : base(path + " " + reason)
        {
            FilePath = path;
            Reason = reason;
        }

        public string FilePath { get; }

        /// <summary>The message without the path.</summary>
        public string Reason { get; }
    }
}
