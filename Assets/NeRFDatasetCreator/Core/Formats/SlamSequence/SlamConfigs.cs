using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config files the SLAM methods read a sequence's camera from, written beside it (YAML, one key a line, the
    /// methods' own key names): SplaTAM's dataset config (its scripts pick the reader from <c>dataset_name</c>), MonoGS's
    /// and Gaussian-SLAM's run configs inheriting the method's own base config for the dataset (every parameter but the
    /// camera and the folder stays the method's). The principal point is ours as COLMAP's convention puts it (the image's
    /// corner at 0): the convention of the Gaussian rasterizers' projection that all three render through.
    /// </summary>
    public static class SlamConfigs
    {
        public static string SplaTam(string datasetName, CameraIntrinsics k, double depthScale)
        {
            var s = new StringBuilder();
            s.Append("# SplaTAM dataset config written by NeRF Dataset Creator: set data.gradslam_data_cfg to this file.\n");
            s.Append("dataset_name: '").Append(datasetName).Append("'\n");
            s.Append("camera_params:\n");
            s.Append("  image_height: ").Append(k.Height).Append('\n');
            s.Append("  image_width: ").Append(k.Width).Append('\n');
            s.Append("  fx: ").Append(N(k.FlX)).Append('\n');
            s.Append("  fy: ").Append(N(k.FlY)).Append('\n');
            s.Append("  cx: ").Append(N(k.Cx)).Append('\n');
            s.Append("  cy: ").Append(N(k.Cy)).Append('\n');
            s.Append("  png_depth_scale: ").Append(N(depthScale)).Append('\n');
            s.Append("  crop_edge: 0\n");
            return s.ToString();
        }

        public static string MonoGs(string baseConfig, CameraIntrinsics k, double depthScale, string folder)
        {
            var s = new StringBuilder();
            s.Append("# MonoGS config written by NeRF Dataset Creator: python slam.py --config <this file> (from MonoGS's folder).\n");
            s.Append("inherit_from: \"").Append(baseConfig).Append("\"\n");
            s.Append("Dataset:\n");
            s.Append("  dataset_path: ").Append(Quoted(folder)).Append('\n');
            s.Append("  Calibration:\n");
            s.Append("    fx: ").Append(N(k.FlX)).Append('\n');
            s.Append("    fy: ").Append(N(k.FlY)).Append('\n');
            s.Append("    cx: ").Append(N(k.Cx)).Append('\n');
            s.Append("    cy: ").Append(N(k.Cy)).Append('\n');
            s.Append("    k1: 0.0\n    k2: 0.0\n    p1: 0.0\n    p2: 0.0\n    k3: 0.0\n");
            s.Append("    width: ").Append(k.Width).Append('\n');
            s.Append("    height: ").Append(k.Height).Append('\n');
            s.Append("    depth_scale: ").Append(N(depthScale)).Append('\n');
            s.Append("    distorted: False\n");
            return s.ToString();
        }

        public static string GaussianSlam(string baseConfig, CameraIntrinsics k, double depthScale, string folder, string sceneName)
        {
            var s = new StringBuilder();
            s.Append("# Gaussian-SLAM config written by NeRF Dataset Creator: python run_slam.py <this file> (from Gaussian-SLAM's folder).\n");
            s.Append("inherit_from: ").Append(baseConfig).Append('\n');
            s.Append("data:\n");
            s.Append("  scene_name: ").Append(Quoted(sceneName)).Append('\n');
            s.Append("  input_path: ").Append(Quoted(folder)).Append('\n');
            s.Append("  output_path: ").Append(Quoted(System.IO.Path.Combine(folder, "gaussian_slam_output"))).Append('\n');
            s.Append("cam:\n");
            s.Append("  H: ").Append(k.Height).Append('\n');
            s.Append("  W: ").Append(k.Width).Append('\n');
            s.Append("  fx: ").Append(N(k.FlX)).Append('\n');
            s.Append("  fy: ").Append(N(k.FlY)).Append('\n');
            s.Append("  cx: ").Append(N(k.Cx)).Append('\n');
            s.Append("  cy: ").Append(N(k.Cy)).Append('\n');
            s.Append("  crop_edge: 0\n");
            s.Append("  depth_scale: ").Append(N(depthScale)).Append('\n');
            return s.ToString();
        }

        /// <summary>A YAML float: round-trip digits, always with a decimal point or exponent so YAML reads a float.</summary>
        static string N(double value)
        {
            var text = SlamSequence.Number(value);
            return text.IndexOf('.') >= 0 || text.IndexOf('E') >= 0 || text.IndexOf('e') >= 0 ? text : text + ".0";
        }

        /// <summary>A single-quoted YAML scalar (a quote inside is doubled): any path reads back as written.</summary>
        static string Quoted(string text) => "'" + text.Replace("'", "''") + "'";
    }
}
