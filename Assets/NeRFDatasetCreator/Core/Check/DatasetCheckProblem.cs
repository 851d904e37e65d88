namespace NerfDatasetCreator
{
    /// <summary>One thing a check found wrong, naming the file, the frame and the check.</summary>
    public sealed class DatasetCheckProblem
    {
        public DatasetCheckProblem(string check, string file, int frame, string message)
        {
            Check = check;
            File = file;
            Frame = frame;
            Message = message;
        }

        /// <summary>The check's name, e.g. "alpha vs mask".</summary>
        public string Check { get; }

        /// <summary>The file the problem is in, relative to the dataset (e.g. "./train/r_3_mask_0000.png"), or the transforms file.</summary>
        public string File { get; }

        /// <summary>The frame's index in its transforms file's <c>frames</c>, or −1 when the problem is not one frame's.</summary>
        public int Frame { get; }

        public string Message { get; }

        public override string ToString() =>
            File + (Frame >= 0 ? " frame " + Frame : "") + " [" + Check + "]: " + Message;
    }
}
