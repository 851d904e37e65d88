using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The names and conventions of a Kubric scene folder as its MOVi loader reads it (google-research/kubric 0ee21e2,
    /// challenges/movi/movi_e.py <c>load_scene_directory</c>, lines 346–434; citations in
    /// Documentation~/maintainers/layouts-flow.md):
    /// <list type="bullet">
    /// <item><c>rgba_%05d.png</c>, <c>forward_flow_%05d.png</c>, <c>backward_flow_%05d.png</c> per frame
    /// (movi_e.py:382–385, <c>f"{key}_{f:05d}.png"</c> for f in range(num_frames)).</item>
    /// <item>Flow channels (Δrow, Δcol) in pixels: Blender's vector pass is (−Δcol, Δrow) and Kubric swaps it
    /// (kubric/renderer/blender_utils.py:237–245).</item>
    /// <item>Backward flow keeps the forward direction of time: <c>backward_flow[t] = p(t) − p(t − 1)</c> at frame t's
    /// pixel, forward <c>forward_flow[t] = p(t + 1) − p(t)</c> (kubric issue #152: "we decided to retain the same
    /// direction of time in both cases"); so backward_flow[t] is the negative of NSFF's and our t → t − 1 flow.</item>
    /// <item>One min/max per layer over the whole video in <c>data_ranges.json</c>; a value is stored as
    /// (v − min) · 65535 / (max − min) (kubric/file_io.py:282–303) and read back as code / 65535 · (max − min) + min
    /// (movi_e.py:72–83).</item>
    /// </list>
    /// </summary>
    public static class Kubric
    {
        public const string FolderName = "kubric";

        /// <summary>The scene folders go one level down, so that the builder's <c>train_val_path</c> lists scene folders only (movi_e.py:286–288 iterates every entry of it).</summary>
        public const string ScenesFolder = "scenes";

        public const string RecordFileName = "kubric_export.json";
        public const string DataRangesFileName = "data_ranges.json";
        public const string MetadataFileName = "metadata.json";
        public const string EventsFileName = "events.json";
        public const string ForwardFlowLayer = "forward_flow";
        public const string BackwardFlowLayer = "backward_flow";
        public const string RgbaLayer = "rgba";

        /// <summary>Kubric's default sensor width in mm (kubric/core/cameras.py:86, <c>sensor_width = tl.Float(36)</c>).</summary>
        public const double SensorWidth = 36;

        /// <summary><c>rgba_00000.png</c>: the loader's <c>f"{key}_{f:05d}.png"</c>.</summary>
        public static string FrameFile(string layer, int frame) => layer + "_" + frame.ToString("00000", CultureInfo.InvariantCulture) + ".png";

        /// <summary>Kubric's camera has one focal length and the principal point at the centre (cameras.py:142–152): anything else is refused.</summary>
        public static ValidationProblem CameraRefusal(CameraIntrinsics k)
        {
            if (Math.Abs(k.FlX - k.FlY) <= 1e-9 * k.FlX && Math.Abs(k.Cx - k.Width / 2.0) <= 1e-9 && Math.Abs(k.Cy - k.Height / 2.0) <= 1e-9) return null;
            return new ValidationProblem("--to", "kubric",
                "describes the camera by focal_length and sensor_width with the principal point at the image centre (kubric/core/cameras.py), but this dataset's camera has fx " + ValidationProblem.Format(k.FlX) +
                ", fy " + ValidationProblem.Format(k.FlY) + ", principal point (" + ValidationProblem.Format(k.Cx) + ", " + ValidationProblem.Format(k.Cy) + ") for " + k.Width + " × " + k.Height + ".",
                "Capture without lens shift.");
        }
    }
}
