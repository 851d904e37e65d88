namespace NerfDatasetCreator
{
    /// <summary>What <see cref="Recovery"/> did about one interrupted operation: finished it, or rolled it back (or could not), in a sentence.</summary>
    public sealed class RecoveryNote
    {
        public RecoveryNote(string operation, bool finished, string text, bool refused = false, bool running = false)
        {
            Running = running;
            Refused = refused;
            Operation = operation;
            Finished = finished;
            Text = text;
        }

        /// <summary>"write" (plan, capture), "merge" or "convert".</summary>
        public string Operation { get; }

        /// <summary>True when the interrupted operation is now complete and in place.</summary>
        public bool Finished { get; }

        public string Text { get; }

        /// <summary>True when recovery refused to act on the operation's journal (a path outside what it owns): nothing was changed.</summary>
        public bool Refused { get; }

        /// <summary>True when the operation's run may still be writing (<see cref="OperationOwner"/>): nothing was changed.</summary>
        public bool Running { get; }

        public override string ToString() => Text;
    }
}
