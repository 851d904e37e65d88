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

        /// <summary>
        /// The self-check of the finished dataset (<see cref="PostCaptureCheck"/>; also in the dataset as
        /// <see cref="DatasetCheck.ReportFileName"/>), or null when the capture did not finish or was not checked.
        /// </summary>
        public DatasetCheckReport Check { get; private set; }

        /// <summary>The dataset was written but its self-check found problems (batch mode then exits 1).</summary>
        public bool CheckFailed => Check != null && Check.Failed;

        /// <summary>This result with <paramref name="check"/> attached and its summary appended to the message.</summary>
        internal DatasetCaptureResult WithCheck(DatasetCheckReport check) =>
            new DatasetCaptureResult(Succeeded, Cancelled, DatasetFolder, PartialFolder,
                Message + "\n" + PostCaptureCheck.Summary(check), Views, ViewsPerSecond) { Check = check };

        public override string ToString() => Message;
    }
}
