using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to shape-of-motion</c>: one video of a dynamic capture with exact tracks as Shape of Motion's iPhone
    /// reader loads it (<see cref="ShapeOfMotion"/>). The video is the train split's (monocular) or its first camera's
    /// (multi-view), the record's first train video; its frames are the track query frames of flow/ — the reader samples
    /// every frame as a query (iphone_dataset.py:250–261, 605–607), so each needs tracks of its own, and n frames give
    /// n² track files: choose fewer query frames (flow.tracks.queryFrames) for a subset. The frames get time ids 0 … n − 1
    /// (the reader indexes w2cs by time id, iphone_dataset.py:653–658), val stays empty. Refused without flow/flow.json,
    /// without tracks of that video, or with fewer than <see cref="ShapeOfMotion.MinFrames"/> query frames.
    /// </summary>
    public static class ShapeOfMotionExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            const string target = "shape-of-motion";
            var root = scene.RootDirectory;
            var record = ShapeOfMotion.Require(root, target);
            var video = record.Videos.FirstOrDefault(v => v.Split == "train");
            var tracks = video == null ? new List<FlowRecordTracks>() : record.Tracks.Where(t => t.Video == video.Name).OrderBy(t => t.QueryFrame).ToList();
            if (tracks.Count == 0)
                throw NerfiesViews.Refuse("flow.tracks", video?.Name ?? "train",
                    "has no tracks: --to " + target + " exports the track query frames of the train video (flow/flow.json \"tracks\"), and there are none.",
                    "Compute flow with tracks from every frame to export (nerf-dataset flow <dataset> --tracks 0,1,2,… or flow.tracks.queryFrames), into a copy of the dataset or after moving flow/ away.");
            if (tracks.Count < ShapeOfMotion.MinFrames)
                throw NerfiesViews.Refuse("flow.tracks", tracks.Count + " query frames",
                    "are fewer than the " + ShapeOfMotion.MinFrames + " Shape of Motion's iPhone reader needs: it normalises the scene from tracks sampled every frames // 10 frames, a step of 0 below 10 (flow3d/data/iphone_dataset.py:314–316).",
                    "Compute tracks from at least " + ShapeOfMotion.MinFrames + " frames of the video (nerf-dataset flow <dataset> --tracks 0,1,2,…).");
            if (scene.Frames.Any(f => f.DepthPath == null && f.Split == "train"))
                throw NerfiesViews.Refuse("depth", "train",
                    "has images without depth, and --to " + target + " writes depth/1x/<id>.npy, which Shape of Motion reads with --data.depth-type lidar (iphone_dataset.py:192–198).",
                    "Capture with depth (depth: png in the train split).");
            var frames = tracks.Select(t => scene.Frames.First(f => f.ImagePath == video.Frames[t.QueryFrame].Image)).ToList();
            var views = frames.Select((f, i) => new NerfiesView(f, true, 0, i)).ToList();
            if (tracks.Count > 1)
            {
                var gaps = tracks.Zip(tracks.Skip(1), (a, b) => b.QueryFrame - a.QueryFrame).Distinct().ToList();
                if (gaps.Count > 1)
                    warnings.Add(new ValidationProblem("flow.tracks", string.Join(", ", tracks.Select(t => t.QueryFrame)),
                        "are not evenly spaced, and Shape of Motion takes the time of frame i as i (its time ids, iphone_dataset.py:102–103), so its motion runs unevenly in time.",
                        "Choose evenly spaced query frames (every k-th frame)."));
            }

            outDir = Path.GetFullPath(outDir);
            var tracksDir = Path.Combine(outDir, ShapeOfMotion.TracksFolder.Replace('/', Path.DirectorySeparatorChar));
            var masksDir = Path.Combine(outDir, ShapeOfMotion.MasksFolder.Replace('/', Path.DirectorySeparatorChar));
            var keypointDir = Path.Combine(outDir, ShapeOfMotion.KeypointFolder.Replace('/', Path.DirectorySeparatorChar));
            foreach (var path in new[] { Path.Combine(outDir, "flow3d_preprocessed"), Path.Combine(outDir, "keypoint") })
                DatasetConverter.EnsureAbsent(path);
            var written = DyCheckExport.WriteLayout(scene, views, target, outDir, staged, warnings, tracks.Count - 1, out var datasetFile);

            var files = tracks.Select(t => FlowTracksFile.Read(ShapeOfMotion.Full(root, t.File))).ToList();
            for (var a = 0; a < tracks.Count; a++)
            {
                var mask = ShapeOfMotion.TargetMask(root, record, video.Name, tracks[a].QueryFrame, out var w, out var h);
                if (mask == null)
                    throw NerfiesViews.Refuse("flow.pairs", video.Name + " frame " + tracks[a].QueryFrame,
                        "has no flow pair starting at it, and its foreground mask (flow3d_preprocessed/track_anything) is the target's pixels read from one.",
                        "Compute flow with forward or backward pairs (the default), then convert again.");
                var maskFile = Path.Combine(masksDir, views[a].Id + ".png");
                staged.WriteNewBytes(maskFile, PngWriter.Encode(mask, w, h, PngPixelFormat.Gray8));
                written.Add(maskFile);
                for (var b = 0; b < tracks.Count; b++)
                {
                    var rows = ShapeOfMotion.TrackRows(files[a], tracks[b].QueryFrame, a == b);
                    var file = Path.Combine(tracksDir, views[a].Id + "_" + views[b].Id + ".npy");
                    staged.WriteNewBytes(file, NumpyFiles.Float32Array(rows, files[a].Points, 4));
                    written.Add(file);
                }
            }
            // Keypoints: the first frame's tracks at DyCheck's 10 strided frames, at half size as the reader expects
            // (keypoint/2x, coordinates × 2 / factor: iphone_dataset.py:697–716); its validation stacks them (validator.py:224).
            var subset = ShapeOfMotion.StridedSubset(tracks.Count, ShapeOfMotion.KeypointFrames);
            foreach (var i in subset)
            {
                var file = Path.Combine(keypointDir, views[i].Id + ".json");
                staged.WriteNewText(file, KeypointJson(ShapeOfMotion.KeypointRows(files[0], tracks[i].QueryFrame, 0.5)));
                written.Add(file);
            }
            return new ConversionResult(outDir, datasetFile, written, warnings, new[]
            {
                "python run_training.py --work-dir " + outDir + "-run data:iphone --data.data-dir " + outDir + " --data.depth-type lidar --data.camera-type original   (Shape of Motion)",
            });
        }

        /// <summary>A keypoint file: a (J, 3) list of (x, y, v) (DyCheck docs/DATASETS.md "keypoint/").</summary>
        public static string KeypointJson(float[,] rows)
        {
            var list = new JArray();
            for (var p = 0; p < rows.GetLength(0); p++)
                list.Add(new JArray((double)rows[p, 0], (double)rows[p, 1], (double)rows[p, 2]));
            return ExportJson.Serialise(list);
        }
    }
}
