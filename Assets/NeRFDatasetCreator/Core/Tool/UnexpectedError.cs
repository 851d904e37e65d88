using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The last line of defence of every command: whatever a command cannot handle itself becomes one clear line
    /// on stderr and exit 1 — never a stack trace. Multi-step operations keep a journal, so the line can promise
    /// that the next run of the same command finishes or rolls back what was interrupted.
    /// </summary>
    public static class UnexpectedError
    {
        public static string Describe(string command, Exception e)
        {
            var what = command ?? "nerf-dataset";
            var message = OneLine(e.Message);
            string cause;
            switch (e)
            {
                case PathTooLongException _: cause = "a path is too long for this file system (" + message + "); choose a shorter folder or name"; break;
                case UnauthorizedAccessException _: cause = "permission denied (" + message + "); check the folder's permissions"; break;
                case DirectoryNotFoundException _: cause = "a folder disappeared or does not exist (" + message + ")"; break;
                case FileNotFoundException _: cause = "a file disappeared or does not exist (" + message + ")"; break;
                case IOException _: cause = "a file operation failed (" + message + "); check the disk space and that no other program uses the files"; break;
                case OutOfMemoryException _: cause = "ran out of memory"; break;
                case OperationCanceledException _: cause = "was cancelled"; break;
                default: cause = "stopped on an unexpected " + e.GetType().Name + " (" + message + "); please report it with the command line"; break;
            }
            return "error: " + what + ": " + cause + ". Nothing was overwritten; run the same command again to finish or roll back what was interrupted.";
        }

        static string OneLine(string text) => (text ?? "").Replace("\r", " ").Replace("\n", " ").Trim();
    }
}
