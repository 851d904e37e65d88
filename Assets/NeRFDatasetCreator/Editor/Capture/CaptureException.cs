using System;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A capture cannot start or cannot go on. The message says what happened and what to do; by the time it is
    /// thrown out of a session the user's scene is as it was and no dataset exists under the final name.
    /// </summary>
    public sealed class CaptureException : Exception
    {
        public CaptureException(string message) : base(message)
        {
        }

        public CaptureException(string message, Exception inner) : base(message, inner)
        {
        }
    }
}
