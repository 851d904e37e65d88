using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to kubric</c>: each video of the dataset's <c>flow/</c> as a Kubric / MOVi scene folder
    /// (<see cref="Kubric"/>) under <c>kubric/scenes/&lt;video&gt;/</c>: <c>rgba_%05d.png</c> (RGB over the protocol
    /// background, alpha 255: the loader keeps <c>[..., :3]</c>, movi_e.py:428–431), <c>forward_flow_%05d.png</c> and
    /// <c>backward_flow_%05d.png</c> (16-bit, <see cref="KubricFlowPng"/>), <c>data_ranges.json</c>, <c>metadata.json</c>
    /// and <c>events.json</c> (no collisions). What the edge frames and empty pixels hold: the last frame's forward flow
    /// and the first frame's backward flow are 0 (Kubric renders a frame before and after the video instead,
    /// movi_def_worker.py:187–188; a capture has no such frames); a pixel without target surface, or whose point is
    /// behind the other camera, is 0; a pixel whose point is hidden or outside the image at the other frame keeps its
    /// exact motion (Blender's vector pass is a motion field too). No depth, segmentation, normal or
    /// object_coordinates layers: read the scenes with <c>layers=("rgba", "forward_flow", "backward_flow")</c>.
    /// </summary>
    public static class KubricExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            InvalidParameterException.ThrowIfAny(Llff.LensRefusal(scene.Lens, "kubric"), Kubric.CameraRefusal(scene.Intrinsics));
            var videos = FlowExportInput.Videos(scene, "kubric", out var record);
            FlowExportInput.RequireConsecutivePairs(record, videos, "kubric");
            outDir = Path.GetFullPath(outDir);
            var recordFile = Path.Combine(outDir, Kubric.RecordFileName);
            var scenes = Path.Combine(outDir, Kubric.ScenesFolder);
            foreach (var path in new[] { recordFile, scenes }) DatasetConverter.EnsureAbsent(path);

            var root = scene.RootDirectory;
            var k = scene.Intrinsics;
            var background = ProtocolBackground.For(root);
            var written = new List<string>();
            var described = new JArray();
            foreach (var video in videos)
            {
                var folder = Path.Combine(scenes, video.Name);
                var n = video.Frames.Count;
                // Two passes: the range of each layer over the whole video first (data_ranges.json), then the PNGs.
                var forwardRange = Range(root, video, k, true);
                var backwardRange = Range(root, video, k, false);
                for (var t = 0; t < n; t++)
                {
                    var image = ExportRgb.Decode(Path.Combine(root, video.Frames[t].ImagePath), video.Frames[t].ImagePath);
                    var rgb = ExportRgb.Rgb(image, (background.R, background.G, background.B));
                    var rgba = new byte[image.Width * image.Height * 4];
                    for (var p = 0; p < image.Width * image.Height; p++)
                    {
                        rgba[4 * p] = rgb[3 * p];
                        rgba[4 * p + 1] = rgb[3 * p + 1];
                        rgba[4 * p + 2] = rgb[3 * p + 2];
                        rgba[4 * p + 3] = 255;
                    }
                    Put(staged, written, Path.Combine(folder, Kubric.FrameFile(Kubric.RgbaLayer, t)), PngWriter.Encode(rgba, image.Width, image.Height, PngPixelFormat.Rgba8));
                    Put(staged, written, Path.Combine(folder, Kubric.FrameFile(Kubric.ForwardFlowLayer, t)), Layer(root, video, k, t, true, forwardRange));
                    Put(staged, written, Path.Combine(folder, Kubric.FrameFile(Kubric.BackwardFlowLayer, t)), Layer(root, video, k, t, false, backwardRange));
                }
                var ranges = new JObject
                {
                    [Kubric.ForwardFlowLayer] = new JObject { ["min"] = forwardRange.Min, ["max"] = forwardRange.Max },
                    [Kubric.BackwardFlowLayer] = new JObject { ["min"] = backwardRange.Min, ["max"] = backwardRange.Max },
                };
                PutText(staged, written, Path.Combine(folder, Kubric.DataRangesFileName), ranges);
                PutText(staged, written, Path.Combine(folder, Kubric.MetadataFileName), Metadata(video, k, background.Name));
                PutText(staged, written, Path.Combine(folder, Kubric.EventsFileName), new JObject { ["collisions"] = new JArray() });
                described.Add(new JObject
                {
                    ["folder"] = Kubric.ScenesFolder + "/" + video.Name,
                    ["video"] = video.Name,
                    ["split"] = video.Record.Split,
                    ["camera_id"] = video.Record.CameraId.HasValue ? (JToken)video.Record.CameraId.Value : JValue.CreateNull(),
                    ["frames"] = new JArray(video.Record.Frames.Select(f => (object)f.Image).ToArray()),
                });
            }
            PutText(staged, written, recordFile, Record(described, background.Name));
            return new ConversionResult(outDir, scenes, written, warnings, new[]
            {
                "Kubric / MOVi: from challenges/movi/movi_e.py, load_scene_directory(\"" + Path.Combine(scenes, videos[0].Name) + "\", (" + k.Height + ", " + k.Width + "), layers=(\"rgba\", \"forward_flow\", \"backward_flow\"))   (one scene folder per video under " + scenes + ")",
            });
        }

        /// <summary>The (min, max) of a layer's (Δrow, Δcol) over every frame of the video, the zero frames and pixels included (Kubric's np.min / np.max of the whole batch, file_io.py:289–290).</summary>
        static (double Min, double Max) Range(string root, FlowExportVideo video, CameraIntrinsics k, bool forward)
        {
            double min = 0, max = 0; // the edge frame is all 0
            for (var t = 0; t < video.Frames.Count; t++)
            {
                var values = RowCol(root, video, k, t, forward);
                if (values == null) continue;
                foreach (var v in values)
                {
                    if (v < min) min = v;
                    if (v > max) max = v;
                }
            }
            return (min, max);
        }

        /// <summary>
        /// Frame t's layer as Kubric defines it, (Δrow, Δcol) per pixel: forward = our flow t → t + 1 as (dy, dx);
        /// backward = −(our flow t → t − 1) as (−dy, −dx), i.e. p(t) − p(t − 1); 0 where the flow is NaN. Null for the
        /// frame without that neighbour (all 0).
        /// </summary>
        internal static float[] RowCol(string root, FlowExportVideo video, CameraIntrinsics k, int t, bool forward)
        {
            var other = forward ? t + 1 : t - 1;
            if (other < 0 || other >= video.Frames.Count) return null;
            var flow = FlowExportInput.Flow(root, new FlowPair(video.Name, t, other), k);
            var sign = forward ? 1f : -1f;
            var result = new float[flow.Length];
            for (var p = 0; p < flow.Length; p += 2)
            {
                float dx = flow[p], dy = flow[p + 1];
                if (float.IsNaN(dx) || float.IsNaN(dy)) continue;
                result[p] = sign * dy;
                result[p + 1] = sign * dx;
            }
            return result;
        }

        static byte[] Layer(string root, FlowExportVideo video, CameraIntrinsics k, int t, bool forward, (double Min, double Max) range)
        {
            var values = RowCol(root, video, k, t, forward) ?? new float[2 * k.Width * k.Height];
            var codes = new ushort[values.Length];
            for (var i = 0; i < values.Length; i++) codes[i] = KubricFlowPng.Quantise(values[i], range.Min, range.Max);
            return KubricFlowPng.Encode(codes, k.Width, k.Height);
        }

        /// <summary>
        /// metadata.json with what load_scene_directory reads (movi_e.py:353–374): metadata.resolution [W, H],
        /// num_frames, num_instances, background; camera focal_length (mm), sensor_width, field_of_view, positions and
        /// quaternions (w, x, y, z) per frame (kubric/utils.py:145–156, get_camera_info); instances (none: the flow
        /// belongs to the target's surface, not to Kubric's objects).
        /// </summary>
        static JObject Metadata(FlowExportVideo video, CameraIntrinsics k, string background)
        {
            // Kubric's camera, like Blender's and our OpenGL c2w, looks down its −Z with +Y up, in a +Z-up world (our output frame).
            var focal = k.FlX / k.Width * Kubric.SensorWidth;
            return new JObject
            {
                ["metadata"] = new JObject
                {
                    ["resolution"] = new JArray(k.Width, k.Height),
                    ["num_frames"] = video.Frames.Count,
                    ["num_instances"] = 0,
                    ["background"] = background,
                },
                ["camera"] = new JObject
                {
                    ["focal_length"] = focal,
                    ["sensor_width"] = Kubric.SensorWidth,
                    ["field_of_view"] = 2 * Math.Atan2(Kubric.SensorWidth / 2, focal),
                    ["positions"] = new JArray(video.Frames.Select(f => new JArray(f.CameraToWorld[0, 3], f.CameraToWorld[1, 3], f.CameraToWorld[2, 3])).ToArray()),
                    ["quaternions"] = new JArray(video.Frames.Select(f =>
                    {
                        var m = f.CameraToWorld;
                        var q = Quaterniond.FromBasis(m.Column(0), m.Column(1), m.Column(2));
                        if (q.W < 0) q = new Quaterniond(-q.X, -q.Y, -q.Z, -q.W);
                        return new JArray(q.W, q.X, q.Y, q.Z);
                    }).ToArray()),
                    // Kubric's normalised intrinsics (cameras.py:142–152): f / sensor · 1, the principal point at 0.5, y and z flipped.
                    ["K"] = new JArray(new JArray(k.FlX / k.Width, 0.0, -0.5), new JArray(0.0, -k.FlY / k.Height, -0.5), new JArray(0.0, 0.0, -1.0)),
                },
                ["instances"] = new JArray(),
            };
        }

        static JObject Record(JArray scenes, string background) => new JObject
        {
            ["format"] = "nerf-dataset-kubric",
            ["source"] = FlowLayout.RecordFile,
            ["files"] = new JObject
            {
                ["rgba_%05d.png"] = "frame t's image, RGB over the " + background + " background, alpha 255",
                ["forward_flow_%05d.png"] = "16-bit RGB: R = Δrow, G = Δcol (pixels) of p(t+1) − p(t) from frame t's pixel, B = 0; code = round((v − min) · 65535 / (max − min)), v = code / 65535 · (max − min) + min; the last frame is 0",
                ["backward_flow_%05d.png"] = "16-bit RGB: R = Δrow, G = Δcol of p(t) − p(t−1) from frame t's pixel (Kubric keeps the forward direction of time: the negative of the t → t−1 flow in flow/), B = 0; the first frame is 0",
                ["data_ranges.json"] = "forward_flow and backward_flow {min, max} over the whole video, in pixels",
                ["metadata.json"] = "resolution [W, H], num_frames, the camera per frame (positions, quaternions w x y z, focal_length mm for sensor_width 36), no instances",
                ["events.json"] = "no collisions",
                ["no_surface"] = "0 flow where the pixel shows no target surface or the point is behind the other camera; hidden or outside points keep their motion",
            },
            ["scenes"] = scenes,
        };

        static void Put(StagedOutput staged, List<string> written, string path, byte[] bytes)
        {
            staged.WriteNewBytes(path, bytes);
            written.Add(path);
        }

        static void PutText(StagedOutput staged, List<string> written, string path, JObject json)
        {
            staged.WriteNewText(path, json.ToString(Formatting.Indented) + "\n");
            written.Add(path);
        }
    }
}
