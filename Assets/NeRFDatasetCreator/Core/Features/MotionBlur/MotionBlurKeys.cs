namespace NerfDatasetCreator
{
    /// <summary>
    /// The keys motion blur adds to the transforms files. Per frame: <c>transform_matrix_start</c> and
    /// <c>transform_matrix_end</c> — instant-ngp's (NVlabs/instant-ngp src/nerf_loader.cu, where each frame's
    /// <c>jsonmatrix_start</c> / <c>jsonmatrix_end</c> fall back to <c>transform_matrix</c>) — the content times the
    /// shutter opens and closes (dynamic captures, this plugin's), and <c>sharp_path</c>. At the top:
    /// <c>rolling_shutter</c> [A, B, C, D] (instant-ngp's <c>read_lens</c>; without it instant-ngp trains every pixel at the
    /// start pose, t = 0) and this plugin's <c>motion_blur</c> record.
    /// </summary>
    public static class MotionBlurKeys
    {
        public const string Start = "transform_matrix_start";
        public const string End = "transform_matrix_end";
        public const string OpenSeconds = "shutter_open_seconds";
        public const string CloseSeconds = "shutter_close_seconds";
        public const string SharpPath = "sharp_path";
        public const string RollingShutter = "rolling_shutter";
        public const string Record = "motion_blur";
    }
}
