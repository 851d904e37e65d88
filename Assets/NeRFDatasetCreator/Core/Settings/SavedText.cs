namespace NerfDatasetCreator
{
    /// <summary>
    /// The text last written to (or read from) a file, so that a save can be skipped when nothing changed — e.g. the
    /// window's settings after an editor-wide undo that touched something else.
    /// </summary>
    public sealed class SavedText
    {
        string _saved;

        /// <summary>Records what the file now holds.</summary>
        public void Saved(string text) => _saved = text;

        /// <summary>True when <paramref name="current"/> is not what the file holds (or nothing was recorded yet).</summary>
        public bool Differs(string current) => _saved == null || _saved != current;
    }
}
