using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where the flow output lives (Documentation~/output-format.md, "flow/"): its own folder, one sub-folder per video,
    /// per frame pair <c>flow_&lt;a&gt;_&lt;b&gt;.flo</c>, <c>occluded_&lt;a&gt;_&lt;b&gt;.png</c>, <c>outside_&lt;a&gt;_&lt;b&gt;.png</c>
    /// and <c>scene_flow_&lt;a&gt;_&lt;b&gt;.exr</c> (a and b the frames' positions in the video, 4 digits), per query
    /// frame <c>tracks_&lt;q&gt;.npz</c>, and the record <c>flow/flow.json</c>. All paths relative to the dataset, '/'.
    /// </summary>
    public static class FlowLayout
    {
        public const string Folder = "flow";
        public const string RecordFile = Folder + "/flow.json";

        /// <summary>A monocular capture's one video: its train split.</summary>
        public const string MonocularVideo = "train";

        /// <summary>A multi-view capture's video of camera <paramref name="cameraId"/> of <paramref name="split"/>: <c>train_cam03</c>.</summary>
        public static string MultiViewVideo(string split, int cameraId) => split + "_cam" + cameraId.ToString("00", CultureInfo.InvariantCulture);

        public static string VideoFolder(string video) => Folder + "/" + video;

        static string Pair(int a, int b) => a.ToString("0000", CultureInfo.InvariantCulture) + "_" + b.ToString("0000", CultureInfo.InvariantCulture);

        public static string FlowFile(string video, int a, int b) => VideoFolder(video) + "/flow_" + Pair(a, b) + FloFile.Extension;
        public static string OccludedFile(string video, int a, int b) => VideoFolder(video) + "/occluded_" + Pair(a, b) + ".png";
        public static string OutsideFile(string video, int a, int b) => VideoFolder(video) + "/outside_" + Pair(a, b) + ".png";
        public static string SceneFlowFile(string video, int a, int b) => VideoFolder(video) + "/scene_flow_" + Pair(a, b) + ".exr";
        static readonly System.Text.RegularExpressions.Regex VideoFileName = new System.Text.RegularExpressions.Regex(
            @"^(flow_\d{4,}_\d{4,}\.flo|(occluded|outside)_\d{4,}_\d{4,}\.png|scene_flow_\d{4,}_\d{4,}\.exr|tracks_\d{4,}\.npz)$", System.Text.RegularExpressions.RegexOptions.CultureInvariant);

        /// <summary>Whether <paramref name="name"/> is a file name this layout writes in a video's folder (for OwnDataset's proof).</summary>
        public static bool IsVideoFile(string name) => VideoFileName.IsMatch(name ?? "");

        /// <summary>flow.json, the one file of the flow folder itself.</summary>
        public static bool IsFolderFile(string name) => name == "flow.json";

        public static string TracksFile(string video, int q) => VideoFolder(video) + "/tracks_" + q.ToString("0000", CultureInfo.InvariantCulture) + ".npz";
    }
}
