using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to tum</c>: the train split of a monocular dynamic capture as a TUM RGB-D sequence (<see cref="TumRgbd"/>):
    /// <c>rgb/&lt;t&gt;.png</c> (8-bit RGB over the protocol background, the pixels exact), <c>depth/&lt;t&gt;.png</c>
    /// (16-bit at 5000 per output unit), the three lists with their headers, timestamps from the frames'
    /// <c>time_seconds</c>, and the SplaTAM, MonoGS and Gaussian-SLAM configs.
    /// </summary>
    public static class TumRgbdExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            var frames = SlamSequence.Read(scene, ExportTarget.Tum, warnings);
            var stamps = frames.Select(f => TumRgbd.Timestamp(f.Seconds)).ToList();
            for (var i = 1; i < stamps.Count; i++)
                if (stamps[i] == stamps[i - 1])
                    throw SlamSequence.Refuse("time_seconds", SlamSequence.Number(frames[i - 1].Seconds) + " and " + SlamSequence.Number(frames[i].Seconds) + " s",
                        "are the same TUM timestamp (" + stamps[i] + ": microseconds, also the files' names).", "Capture fewer time steps over the range.");

            outDir = Path.GetFullPath(outDir);
            var lists = new[] { TumRgbd.RgbList, TumRgbd.DepthList, TumRgbd.GroundTruth }.Select(n => Path.Combine(outDir, n)).ToList();
            var folders = new[] { TumRgbd.RgbFolder, TumRgbd.DepthFolder }.Select(n => Path.Combine(outDir, n)).ToList();
            var configs = new[] { TumRgbd.SplaTamConfigFileName, TumRgbd.MonoGsConfigFileName, TumRgbd.GaussianSlamConfigFileName }.Select(n => Path.Combine(outDir, n)).ToList();
            foreach (var path in lists.Concat(folders).Concat(configs)) DatasetConverter.EnsureAbsent(path);

            var sequence = Path.GetFileName(outDir);
            var background = ProtocolBackground.For(scene.RootDirectory);
            var rgbList = new StringBuilder(TumRgbd.Header("color images", sequence, "timestamp filename"));
            var depthList = new StringBuilder(TumRgbd.Header("depth maps", sequence, "timestamp filename"));
            var poses = new StringBuilder(TumRgbd.Header("ground truth trajectory", sequence, "timestamp tx ty tz qx qy qz qw"));
            var written = new List<string>();
            long beyond = 0, pixels = 0;
            for (var i = 0; i < frames.Count; i++)
            {
                var frame = frames[i].Source;
                var name = stamps[i] + ".png";
                var rgb = SlamSequence.Rgb(scene, frame, background, out var w, out var h);
                var colour = Path.Combine(folders[0], name);
                staged.WriteNewBytes(colour, PngWriter.Encode(rgb, w, h, PngPixelFormat.Rgb8));
                var depth = SlamSequence.Depth(scene, frame, TumRgbd.DepthScale, ref beyond, out var dw, out var dh);
                pixels += depth.Length;
                var depthPath = Path.Combine(folders[1], name);
                staged.WriteNewBytes(depthPath, PngWriter.EncodeGray16(depth, dw, dh));
                written.Add(colour);
                written.Add(depthPath);
                rgbList.Append(stamps[i]).Append(' ').Append(TumRgbd.RgbFolder).Append('/').Append(name).Append('\n');
                depthList.Append(stamps[i]).Append(' ').Append(TumRgbd.DepthFolder).Append('/').Append(name).Append('\n');
                poses.Append(TumRgbd.PoseLine(stamps[i], frame.CameraToWorld)).Append('\n');
            }
            staged.WriteNewText(lists[0], rgbList.ToString());
            staged.WriteNewText(lists[1], depthList.ToString());
            staged.WriteNewText(lists[2], poses.ToString());
            staged.WriteNewText(configs[0], TumRgbd.SplaTamConfig(scene.Intrinsics));
            staged.WriteNewText(configs[1], TumRgbd.MonoGsConfig(scene.Intrinsics, outDir));
            staged.WriteNewText(configs[2], TumRgbd.GaussianSlamConfig(scene.Intrinsics, outDir, sequence));
            written.AddRange(lists);
            written.AddRange(configs);

            var kept = TumRgbd.KeptByReaders(stamps);
            if (kept.Count < stamps.Count)
            {
                var first = Enumerable.Range(0, stamps.Count).First(i => !kept.Contains(i));
                warnings.Add(new ValidationProblem(TumRgbd.RgbList, (stamps.Count - kept.Count) + " of " + stamps.Count + " frames (first: " + stamps[first] + ")",
                    "are 1/32 s or less after the frame kept before them, and the TUM readers of SplaTAM, MonoGS and Gaussian-SLAM drop such frames (frame_rate = 32): they train on " + kept.Count + ".",
                    "Capture at most 31 steps a second (time.fps below 32, or fewer steps over the range), or use --to replica, which keeps every frame."));
            }
            var range = SlamSequence.RangeWarning(TumRgbd.DepthFolder, beyond, pixels, TumRgbd.DepthScale, "TUM RGB-D");
            if (range != null) warnings.Add(range);
            return new ConversionResult(outDir, lists[2], written, warnings,
                ReplicaExport.Commands(outDir, scene.Intrinsics, "tum", TumRgbd.SplaTamConfigFileName, TumRgbd.MonoGsConfigFileName, TumRgbd.GaussianSlamConfigFileName));
        }
    }
}
