using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The TUM RGB-D layout as the SLAM readers parse it (SplaTAM tum.py, MonoGS dataset.py TUMParser, Gaussian-SLAM
    /// datasets.py TUM_RGBD, the same code in each; commits and lines in Documentation~/maintainers/layouts-slam.md):
    /// <list type="bullet">
    /// <item><c>rgb.txt</c>, <c>depth.txt</c>: "timestamp filename" lines read by <c>np.loadtxt(delimiter=' ')</c>
    /// (so one space, and '#' lines are comments); <c>groundtruth.txt</c>: "timestamp tx ty tz qx qy qz qw", read with
    /// <c>skiprows=1</c>: its first line is skipped whatever it holds, so the header is not optional.</item>
    /// <item>Association: each colour timestamp takes the nearest depth and pose within 0.08 s; then a frame is kept
    /// only if it is MORE than 1/32 s after the last kept one (<c>t1 - t0 &gt; 1.0 / frame_rate</c>, frame_rate 32).</item>
    /// <item>Pose: camera-to-world of the colour camera, OpenCV axes; the quaternion scalar-last (scipy's
    /// <c>Rotation.from_quat</c>; MonoGS rolls it to trimesh's scalar-first).</item>
    /// <item>Depth: 16-bit PNG divided by 5000 (SplaTAM configs/data/TUM/*.yaml png_depth_scale, MonoGS
    /// configs/rgbd/tum/*.yaml depth_scale, Gaussian-SLAM configs/TUM_RGBD/tum_rgbd.yaml): 65535 codes span 13.107 units.</item>
    /// </list>
    /// </summary>
    public static class TumRgbd
    {
        public const string FolderName = "tum";
        public const string RgbFolder = "rgb";
        public const string DepthFolder = "depth";
        public const string RgbList = "rgb.txt";
        public const string DepthList = "depth.txt";
        public const string GroundTruth = "groundtruth.txt";
        public const double DepthScale = 5000;

        /// <summary>The readers' <c>frame_rate</c>: a frame 1/32 s or less after the last kept one is dropped.</summary>
        public const double ReaderFrameRate = 32;

        public const string SplaTamConfigFileName = "splatam.yaml";
        public const string MonoGsConfigFileName = "monogs.yaml";
        public const string GaussianSlamConfigFileName = "gaussian_slam.yaml";

        /// <summary>A timestamp as TUM writes it: seconds with six decimals (microseconds), the file names' stem too.</summary>
        public static string Timestamp(double seconds) => seconds.ToString("0.000000", CultureInfo.InvariantCulture);

        /// <summary>How many of the (ascending) timestamps the readers keep: their rule, on the values they parse.</summary>
        public static IReadOnlyList<int> KeptByReaders(IReadOnlyList<string> timestamps)
        {
            var kept = new List<int>();
            for (var i = 0; i < timestamps.Count; i++)
            {
                var t = double.Parse(timestamps[i], CultureInfo.InvariantCulture);
                if (kept.Count == 0 || t - double.Parse(timestamps[kept[kept.Count - 1]], CultureInfo.InvariantCulture) > 1.0 / ReaderFrameRate) kept.Add(i);
            }
            return kept;
        }

        /// <summary>The "# …" header lines of each list, as in the TUM sequences (three each).</summary>
        public static string Header(string what, string sequence, string columns) =>
            "# " + what + "\n# file: '" + sequence + "' (NeRF Dataset Creator)\n# " + columns + "\n";

        /// <summary>One groundtruth.txt line: the camera centre and the camera-to-world rotation (OpenCV axes) as a unit quaternion, w ≥ 0.</summary>
        public static string PoseLine(string timestamp, Matrix4x4d cameraToWorldOpenGl)
        {
            // ColmapTextWriter's world-to-camera quaternion (OpenCV axes, re-orthonormalised, w ≥ 0); its conjugate is camera-to-world.
            ColmapTextWriter.WorldToCamera(cameraToWorldOpenGl, out var q, out _);
            var c = cameraToWorldOpenGl.Translation;
            return timestamp + " " + SlamSequence.Number(c.X) + " " + SlamSequence.Number(c.Y) + " " + SlamSequence.Number(c.Z) + " " +
                SlamSequence.Number(-q.X) + " " + SlamSequence.Number(-q.Y) + " " + SlamSequence.Number(-q.Z) + " " + SlamSequence.Number(q.W);
        }

        public static string SplaTamConfig(CameraIntrinsics k) => SlamConfigs.SplaTam("tum", k, DepthScale);

        public static string MonoGsConfig(CameraIntrinsics k, string folder) => SlamConfigs.MonoGs("configs/rgbd/tum/base_config.yaml", k, DepthScale, folder);

        public static string GaussianSlamConfig(CameraIntrinsics k, string folder, string sceneName) =>
            SlamConfigs.GaussianSlam("configs/TUM_RGBD/tum_rgbd.yaml", k, DepthScale, folder, sceneName);
    }
}
