using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to replica</c>: the train split of a monocular dynamic capture as a Replica RGB-D sequence
    /// (<see cref="Replica"/>): <c>results/frame%06d.jpg</c> (JPEG at <see cref="JpegWriter.Quality"/>, RGB over the
    /// protocol background), <c>results/depth%06d.png</c> (16-bit at 6553.5 per output unit), <c>traj.txt</c>, and
    /// the SplaTAM, MonoGS and Gaussian-SLAM configs. Frames in time order (<see cref="SlamSequence"/>).
    /// </summary>
    public static class ReplicaExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            var frames = SlamSequence.Read(scene, ExportTarget.Replica, warnings);
            outDir = Path.GetFullPath(outDir);
            var results = Path.Combine(outDir, Replica.ResultsFolder);
            var traj = Path.Combine(outDir, Replica.TrajectoryFileName);
            var configs = new[] { Replica.SplaTamConfigFileName, Replica.MonoGsConfigFileName, Replica.GaussianSlamConfigFileName }.Select(n => Path.Combine(outDir, n)).ToList();
            foreach (var path in new[] { results, traj }.Concat(configs)) DatasetConverter.EnsureAbsent(path);

            var background = ProtocolBackground.For(scene.RootDirectory);
            var written = new List<string>();
            var lines = new StringBuilder();
            long beyond = 0, pixels = 0;
            for (var i = 0; i < frames.Count; i++)
            {
                var frame = frames[i].Source;
                var rgb = SlamSequence.Rgb(scene, frame, background, out var w, out var h);
                var colour = Path.Combine(results, Replica.ColourName(i));
                staged.WriteNewBytes(colour, JpegWriter.EncodeRgb(rgb, w, h));
                var depth = SlamSequence.Depth(scene, frame, Replica.DepthScale, ref beyond, out var dw, out var dh);
                pixels += depth.Length;
                var depthPath = Path.Combine(results, Replica.DepthName(i));
                staged.WriteNewBytes(depthPath, PngWriter.EncodeGray16(depth, dw, dh));
                written.Add(colour);
                written.Add(depthPath);
                lines.Append(Replica.TrajectoryLine(frame.CameraToWorld)).Append('\n');
            }
            staged.WriteNewText(traj, lines.ToString());
            written.Add(traj);
            var sceneName = Path.GetFileName(outDir);
            staged.WriteNewText(configs[0], Replica.SplaTamConfig(scene.Intrinsics));
            staged.WriteNewText(configs[1], Replica.MonoGsConfig(scene.Intrinsics, outDir));
            staged.WriteNewText(configs[2], Replica.GaussianSlamConfig(scene.Intrinsics, outDir, sceneName));
            written.AddRange(configs);
            var range = SlamSequence.RangeWarning(Replica.ResultsFolder, beyond, pixels, Replica.DepthScale, "Replica");
            if (range != null) warnings.Add(range);
            return new ConversionResult(outDir, traj, written, warnings, Commands(outDir, scene.Intrinsics, "replica", Replica.SplaTamConfigFileName, Replica.MonoGsConfigFileName, Replica.GaussianSlamConfigFileName));
        }

        /// <summary>The three methods' commands, each run from the method's own folder (SplaTAM's config is Python: four values to set).</summary>
        public static IReadOnlyList<string> Commands(string outDir, CameraIntrinsics k, string splatamConfigs, string splatam, string monogs, string gaussianSlam) => new[]
        {
            "SplaTAM: in configs/" + splatamConfigs + "/splatam.py set data basedir='" + Path.GetDirectoryName(outDir) + "', sequence='" + Path.GetFileName(outDir) +
                "', gradslam_data_cfg='" + Path.Combine(outDir, splatam) + "', desired_image_height=" + k.Height + ", desired_image_width=" + k.Width +
                ", then: python scripts/splatam.py configs/" + splatamConfigs + "/splatam.py",
            "MonoGS: python slam.py --config " + Path.Combine(outDir, monogs),
            "Gaussian-SLAM: python run_slam.py " + Path.Combine(outDir, gaussianSlam),
        };
    }
}
