using System.Globalization;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The Replica sequence layout of the SLAM methods (NICE-SLAM's rendering of Replica), each rule from the readers'
    /// code (commits and lines in Documentation~/maintainers/layouts-slam.md):
    /// <list type="bullet">
    /// <item><c>results/frame*.jpg</c> and <c>results/depth*.png</c>, globbed and sorted (SplaTAM replica.py:45–46 with
    /// natsort, MonoGS dataset.py:22–23 and Gaussian-SLAM datasets.py:51–54 with a plain sort): six-digit zero-padded
    /// indices sort the same either way.</item>
    /// <item><c>traj.txt</c>: line i is frame i's camera-to-world, 16 numbers row-major, OpenCV camera axes (SplaTAM
    /// replica.py:56–62 uses it as read, the axis flips commented out; MonoGS dataset.py:35–36 inverts it to
    /// world-to-camera; Gaussian-SLAM datasets.py:62–64 reads every line, so no blank line may follow).</item>
    /// <item>Depth: 16-bit PNG divided by <c>png_depth_scale</c> / <c>depth_scale</c>, 6553.5 in all three configs
    /// (SplaTAM configs/data/replica.yaml:9, MonoGS configs/rgbd/replica/base_config.yaml:29, Gaussian-SLAM
    /// configs/Replica/replica.yaml:42): 65535 codes span 10 output units.</item>
    /// </list>
    /// </summary>
    public static class Replica
    {
        public const string FolderName = "replica";
        public const string ResultsFolder = "results";
        public const string TrajectoryFileName = "traj.txt";
        public const double DepthScale = 6553.5;

        /// <summary>The three methods' config files, written beside <c>results/</c>.</summary>
        public const string SplaTamConfigFileName = "splatam.yaml";
        public const string MonoGsConfigFileName = "monogs.yaml";
        public const string GaussianSlamConfigFileName = "gaussian_slam.yaml";

        public static string ColourName(int index) => "frame" + index.ToString("D6", CultureInfo.InvariantCulture) + ".jpg";
        public static string DepthName(int index) => "depth" + index.ToString("D6", CultureInfo.InvariantCulture) + ".png";

        /// <summary>One traj.txt line: the OpenCV camera-to-world matrix, row-major, space-separated, round-trip numbers.</summary>
        public static string TrajectoryLine(Matrix4x4d cameraToWorldOpenGl)
        {
            var m = SlamSequence.CameraToWorldOpenCv(cameraToWorldOpenGl);
            var line = new StringBuilder();
            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                {
                    if (line.Length > 0) line.Append(' ');
                    line.Append(SlamSequence.Number(m[r, c]));
                }
            return line.ToString();
        }

        /// <summary>SplaTAM's dataset config (<c>gradslam_data_cfg</c>): configs/data/replica.yaml with our camera; basedataset.py:125–134 reads these keys.</summary>
        public static string SplaTamConfig(CameraIntrinsics k) => SlamConfigs.SplaTam("replica", k, DepthScale);

        /// <summary>MonoGS's config: its Replica base config with our camera and folder (dataset.py:212–246 reads the Calibration keys).</summary>
        public static string MonoGsConfig(CameraIntrinsics k, string folder) =>
            SlamConfigs.MonoGs("configs/rgbd/replica/base_config.yaml", k, DepthScale, folder);

        /// <summary>Gaussian-SLAM's config: its Replica config with our camera and folder (datasets.py:15–25 reads the cam keys).</summary>
        public static string GaussianSlamConfig(CameraIntrinsics k, string folder, string sceneName) =>
            SlamConfigs.GaussianSlam("configs/Replica/replica.yaml", k, DepthScale, folder, sceneName);
    }
}
