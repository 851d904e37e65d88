namespace NerfDatasetCreator.Editor
{
    /// <summary>How a capture ended, in one paragraph a user can act on.</summary>
    public sealed class DatasetCaptureResult
    {
        internal DatasetCaptureResult(bool succeeded, bool cancelled, string datasetFolder, string partialFolder,
            string message, int views, double viewsPerSecond)
        {
            Succeeded = succeeded;
            Cancelled = cancelled;
            DatasetFolder = datasetFolder;
            PartialFolder = partialFolder;
            Message = message;
            Views = views;
            ViewsPerSecond = viewsPerSecond;
        }

        public bool Succeeded { get; }
        public bool Cancelled { get; }

        /// <summary>The finished dataset (when <see cref="Succeeded"/>).</summary>
        public string DatasetFolder { get; }

        /// <summary>Where an unfinished run left its files (nothing is ever left under the final name); may be null.</summary>
        public string PartialFolder { get; }

        public string Message { get; }
        public int Views { get; }
        public double ViewsPerSecond { get; }

        public override string ToString() => Message;
    }
}
