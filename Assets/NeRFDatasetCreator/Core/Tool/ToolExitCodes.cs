namespace NerfDatasetCreator
{
    /// <summary>The exit codes of every command, in the headless tool and in Unity's Dataset Tools alike.</summary>
    public static class ToolExitCodes
    {
        public const int Success = 0;

        /// <summary>Problems found, refused or failed.</summary>
        public const int Failure = 1;

        /// <summary>A usage, config or settings error.</summary>
        public const int UsageError = 2;
    }
}
