namespace NerfDatasetCreator
{
    /// <summary>
    /// HDR-NeRF's synthetic layout (xhuangcv/hdr-nerf <c>load_syn_llff.py</c> at 41bde0f, <c>load_syn_llff_data</c>):
    /// <c>transforms_train.json</c> and <c>transforms_test.json</c> (only those two splits, :85), each with
    /// <c>exposure_&lt;split&gt;.json</c> beside it (:89–90), a map from <c>file_path + '_&lt;k&gt;.png'</c> to that
    /// image's exposure time (:105, :111), and five images per view, k = 0 … 4 (<c>num_exps = 5</c>, :96): training
    /// picks one of k = 0, 2, 4 per view (:102), testing reads all five (:108–111). <c>camera_angle_x</c> gives the focal
    /// (:133–134).
    /// </summary>
    public static class HdrNerf
    {
        public const string FolderName = "hdr-nerf";

        /// <summary>The splits the loader reads (:85): val is not exported.</summary>
        public static readonly string[] Splits = { "train", "test" };

        /// <summary>
        /// The five exposure times, in units of the capture's own exposure: two stops apart and centred on it, so image
        /// k = 2 is the dataset's PNG (no exposure feature) and k = 0 … 4 span ±4 EV.
        /// </summary>
        public static readonly double[] ExposureTimes = { 1.0 / 16, 1.0 / 4, 1, 4, 16 };

        public static string ExposureFileName(string split) => "exposure_" + split + ".json";

        /// <summary>The k-th image of a frame whose <c>file_path</c> is <paramref name="stem"/> (no extension), as the loader names it (:104).</summary>
        public static string ImagePath(string stem, int k) => stem + "_" + k.ToString(System.Globalization.CultureInfo.InvariantCulture) + ".png";
    }
}
