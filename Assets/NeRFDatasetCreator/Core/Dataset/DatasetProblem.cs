using System;

namespace NerfDatasetCreator
{
    /// <summary>One thing wrong with a dataset on disk, naming the file and, where there is one, the frame.</summary>
    [Serializable]
    public sealed class DatasetProblem
    {
        public DatasetProblem(string file, int frameIndex, string framePath, string message)
        {
            File = file ?? "";
            FrameIndex = frameIndex;
            FramePath = framePath;
            Message = message ?? "";
        }

        /// <summary>The transforms file (or other dataset file) the problem belongs to, relative to the dataset.</summary>
        public string File { get; }

        /// <summary>The frame's index in <c>frames</c>, or −1 for a problem of the whole file.</summary>
        public int FrameIndex { get; }

        /// <summary>The frame's <c>file_path</c>, when it has one.</summary>
        public string FramePath { get; }

        public string Message { get; }

        /// <summary>One line: <c>transforms_train.json frame 3 (./train/r_3): image ./train/r_3.png is missing</c>.</summary>
        public override string ToString()
        {
            var where = File;
            if (FrameIndex >= 0) where += " frame " + FrameIndex + (string.IsNullOrEmpty(FramePath) ? "" : " (" + FramePath + ")");
            return where + ": " + Message;
        }
    }
}
