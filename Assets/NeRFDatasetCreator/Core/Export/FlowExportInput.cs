using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One video of <c>flow/flow.json</c> with each frame's dataset view (pose, depth) beside it.</summary>
    public sealed class FlowExportVideo
    {
        public FlowExportVideo(FlowRecordVideo record, IReadOnlyList<ExportFrame> frames)
        {
            Record = record;
            Frames = frames;
        }

        public FlowRecordVideo Record { get; }
        public string Name => Record.Name;

        /// <summary>The dataset's view of each frame of the video, in the video's order.</summary>
        public IReadOnlyList<ExportFrame> Frames { get; }
    }

    /// <summary>
    /// What a flow layout (<c>--to kubric</c>, <c>--to nsff</c>) reads of the dataset's <c>flow/</c>: the record
    /// (<see cref="FlowRecord.Read"/>), each video's frames matched to the dataset's views by image path, and the pairs
    /// between consecutive frames (span 1), read through <see cref="FloFile"/> and the PNG/EXR readers — never by guessing
    /// file names. A dataset without the record, or a record without the pairs a layout needs, is refused naming the fix.
    /// </summary>
    public static class FlowExportInput
    {
        /// <summary>The videos of the dataset's flow record; refused when there is none or a frame is not a view of the dataset.</summary>
        public static IReadOnlyList<FlowExportVideo> Videos(ExportScene scene, string target, out FlowRecord record)
        {
            try { record = FlowRecord.Read(scene.RootDirectory); }
            catch (InvalidDataException e)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem(FlowLayout.RecordFile, "unreadable", e.Message, "Delete flow/ (written by nerf-dataset flow) and run nerf-dataset flow <dataset> again.") });
            }
            if (record == null)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(FlowLayout.RecordFile, "missing",
                        "is what --to " + target + " reads its optical flow from, and this dataset has no flow yet.",
                        "Run nerf-dataset flow <dataset> first (a dynamic capture with \"geometryPack\": \"everyStep\"), or capture with the settings' \"flow\" section."),
                });
            var byImage = scene.Frames.GroupBy(f => f.ImagePath.Replace('\\', '/'), StringComparer.Ordinal).ToDictionary(g => g.Key, g => g.First(), StringComparer.Ordinal);
            var videos = new List<FlowExportVideo>();
            foreach (var video in record.Videos)
            {
                var frames = new List<ExportFrame>();
                foreach (var f in video.Frames)
                {
                    if (!byImage.TryGetValue(f.Image.Replace('\\', '/'), out var frame))
                        throw new InvalidParameterException(new[]
                        {
                            new ValidationProblem(FlowLayout.RecordFile, f.Image, "is a frame of video " + video.Name + " but not a view of the dataset's transforms files.",
                                "Delete flow/ (written by nerf-dataset flow) and run nerf-dataset flow <dataset> again."),
                        });
                    frames.Add(frame);
                }
                videos.Add(new FlowExportVideo(video, frames));
            }
            if (videos.Count == 0)
                throw new InvalidParameterException(new[] { new ValidationProblem(FlowLayout.RecordFile, "no videos", "lists no video to export.", "Run nerf-dataset flow <dataset> on a dynamic capture.") });
            return videos;
        }

        /// <summary>
        /// Refuses a record that lacks a consecutive pair of a video: the forward pair (a, a + 1) of every frame but the
        /// last and the backward pair (a, a − 1) of every frame but the first, which both layouts read.
        /// </summary>
        public static void RequireConsecutivePairs(FlowRecord record, IReadOnlyList<FlowExportVideo> videos, string target)
        {
            var pairs = new HashSet<(string, int, int)>(record.Pairs.Select(p => (p.Video, p.From, p.To)));
            foreach (var v in videos)
            {
                var n = v.Frames.Count;
                if (n < 2)
                    throw new InvalidParameterException(new[] { new ValidationProblem("video", v.Name, "has " + n + " frame, and --to " + target + " needs flow between frames.", "Capture at least two time steps.") });
                for (var a = 0; a < n; a++)
                    foreach (var b in new[] { a + 1, a - 1 })
                        if (b >= 0 && b < n && !pairs.Contains((v.Name, a, b)))
                            throw new InvalidParameterException(new[]
                            {
                                new ValidationProblem(FlowLayout.RecordFile, v.Name + " " + a + " → " + b,
                                    "is missing: --to " + target + " reads the forward and the backward flow between consecutive frames (span 1).",
                                    "Delete flow/ (written by nerf-dataset flow) and run nerf-dataset flow <dataset> again with span 1 and backward flow (the defaults)."),
                            });
            }
        }

        /// <summary>The flow of the pair a → b: (dx, dy) per pixel, rows top first, NaN where there is none; its size must be the dataset's.</summary>
        public static float[] Flow(string root, FlowPair pair, CameraIntrinsics k)
        {
            var flow = FloFile.Read(Path.Combine(root, pair.FlowFile.Replace('/', Path.DirectorySeparatorChar)), out var w, out var h);
            if (w != k.Width || h != k.Height)
                throw new InvalidParameterException(new[] { new ValidationProblem(pair.FlowFile, w + " × " + h, "is not the dataset's image size " + k.Width + " × " + k.Height + ".", "Delete flow/ and run nerf-dataset flow <dataset> again.") });
            return flow;
        }

        /// <summary>An 8-bit grey mask of the pair (occluded or outside): true where it is 255.</summary>
        public static bool[] Mask(string root, string file, CameraIntrinsics k)
        {
            var image = PngReader.Read(Path.Combine(root, file.Replace('/', Path.DirectorySeparatorChar)));
            if (image.Width != k.Width || image.Height != k.Height || image.BitDepth != 8 || image.Channels != 1)
                throw new InvalidParameterException(new[] { new ValidationProblem(file, image.Width + " × " + image.Height, "is not an 8-bit grey mask of the dataset's image size.", "Delete flow/ and run nerf-dataset flow <dataset> again.") });
            var mask = new bool[image.Samples.Length];
            for (var i = 0; i < mask.Length; i++) mask[i] = image.Samples[i] != 0;
            return mask;
        }

        /// <summary>
        /// Where the pair's scene flow is not zero: RGB (the point's motion, output units) ≠ 0 on the target (A = 1). Needs
        /// the record's scene flow (refused otherwise, naming the fix).
        /// </summary>
        public static bool[] Moving(string root, FlowPair pair, CameraIntrinsics k)
        {
            var path = Path.Combine(root, pair.SceneFlowFile.Replace('/', Path.DirectorySeparatorChar));
            var image = ExrReader.Read(path);
            float[] r = image.Channel("R"), g = image.Channel("G"), b = image.Channel("B"), a = image.Channel("A");
            if (image.Width != k.Width || image.Height != k.Height || r == null || g == null || b == null || a == null)
                throw new InvalidParameterException(new[] { new ValidationProblem(pair.SceneFlowFile, image.Width + " × " + image.Height, "is not an RGBA scene-flow image of the dataset's size.", "Delete flow/ and run nerf-dataset flow <dataset> again.") });
            var moving = new bool[r.Length];
            for (var i = 0; i < moving.Length; i++) moving[i] = a[i] != 0 && (r[i] != 0 || g[i] != 0 || b[i] != 0);
            return moving;
        }
    }
}
