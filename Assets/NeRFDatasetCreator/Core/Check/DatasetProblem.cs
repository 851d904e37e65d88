using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One thing wrong with a dataset on disk, as <c>nerf-dataset validate</c> and <c>nerf-dataset check</c> both report
    /// it: the file, the frame where there is one, and — for <c>check</c> — the check that found it. (Settings and other
    /// inputs are reported as <see cref="ValidationProblem"/>s: a key, its value, the reason and the fix.)
    /// </summary>
    [Serializable]
    public sealed class DatasetProblem
    {
        /// <summary>A problem a check found (<see cref="IViewCheck"/>, <see cref="DatasetCheck"/>).</summary>
        public DatasetProblem(string check, string file, int frame, string message)
        {
            Check = check;
            File = file;
            Frame = frame;
            Message = message;
        }

        DatasetProblem(string file, int frame, string framePath, string message)
        {
            File = file ?? "";
            Frame = frame;
            FramePath = framePath;
            Message = message ?? "";
        }

        /// <summary>A problem of the dataset's structure that <see cref="DatasetValidator"/> found, naming the frame's <c>file_path</c> when it has one.</summary>
        public static DatasetProblem Structure(string file, int frame, string framePath, string message) =>
            new DatasetProblem(file, frame, framePath, message);

        /// <summary>The check's name, e.g. "alpha vs mask"; null for a structural problem (<see cref="Structure"/>).</summary>
        public string Check { get; }

        /// <summary>The file the problem is in, relative to the dataset (e.g. "./train/r_3_mask_0000.png"), or the transforms file.</summary>
        public string File { get; }

        /// <summary>The frame's index in its transforms file's <c>frames</c>, or −1 when the problem is not one frame's.</summary>
        public int Frame { get; }

        /// <summary>The frame's <c>file_path</c>, when a structural problem names it.</summary>
        public string FramePath { get; }

        public string Message { get; }

        /// <summary>
        /// One line. A check's: <c>./train/r_3_mask_0000.png frame 3 [alpha vs mask]: …</c>; a structural one's:
        /// <c>transforms_train.json frame 3 (./train/r_3): image ./train/r_3.png is missing</c>.
        /// </summary>
        public override string ToString()
        {
            if (Check != null) return File + (Frame >= 0 ? " frame " + Frame : "") + " [" + Check + "]: " + Message;
            var where = File;
            if (Frame >= 0) where += " frame " + Frame + (string.IsNullOrEmpty(FramePath) ? "" : " (" + FramePath + ")");
            return where + ": " + Message;
        }
    }
}
