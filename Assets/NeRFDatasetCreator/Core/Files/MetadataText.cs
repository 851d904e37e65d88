using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The text of one of the dataset's small metadata files (labels.json, shard.json), or an
    /// <see cref="InvalidParameterException"/> naming the file, what is wrong and the fix: the read that each of those
    /// readers starts with. The size cap and fault injection are <see cref="FileOps.ReadText"/>'s.
    /// </summary>
    public static class MetadataText
    {
        /// <param name="whyMissing">The sentence for a missing file ("does not exist, so …").</param>
        /// <param name="fixMissing">What to do about a missing file.</param>
        /// <param name="fixUnreadable">What to do about a file that exists but cannot be read.</param>
        public static string Read(string path, string whyMissing, string fixMissing, string fixUnreadable)
        {
            if (!File.Exists(path))
                throw new InvalidParameterException(new[] { new ValidationProblem(path, "(missing)", whyMissing, fixMissing) });
            try
            {
                return FileOps.ReadText(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem(path, "(unreadable)", "cannot be read: " + e.Message, fixUnreadable) });
            }
        }
    }
}
