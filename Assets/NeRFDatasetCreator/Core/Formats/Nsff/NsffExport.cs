using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to nsff</c>: each video of the dataset's <c>flow/</c> as an NSFF scene folder (<see cref="Nsff"/>)
    /// under <c>nsff/&lt;video&gt;/</c> — a monocular capture has one (<c>train</c>), a multi-view capture one per camera
    /// and split (NSFF trains on one monocular video, so each camera's video is its own scene). Per frame t:
    /// <c>images/%05d.png</c> and the same in <c>images_&lt;W&gt;x&lt;H&gt;/</c> (RGB over the protocol background);
    /// <c>disp/%05d.npy</c> = 1 / z from the depth PNG (z along the camera axis, output units; 0 where there is no
    /// surface), where NSFF reads MiDaS's relative disparity and compares it scale- and shift-free
    /// (run_nerf_helpers.py:302–314); <c>motion_masks/%05d.png</c> = 255 where the pixel's point moves (its scene flow
    /// to frame t ± 1 is not 0); <c>flow_i1/%05d_fwd.npz</c> (t → t + 1, every frame but the last) and
    /// <c>%05d_bwd.npz</c> (t → t − 1, every frame but the first), exactly the frames NSFF's RAFT script writes
    /// (run_flows_video.py:416–417) and its trainer reads (run_nerf.py:347–360): <c>flow</c> (H, W, 2) float32
    /// (dx, dy) in pixels — NSFF adds it to the pixel grid (run_nerf.py:317, 410–411), the same displacement from the
    /// pixel centre as ours, and its backward flow is t → t − 1 like ours (the negative of Kubric's) — 0 where there is
    /// none; <c>mask</c> (H, W) uint8 1 where the point is visible in the other frame, 0 where it is hidden, outside,
    /// or there is no surface. <c>poses_bounds.npy</c> as LLFF (<see cref="Llff.Row"/>, <see cref="DepthBounds"/>).
    /// </summary>
    public static class NsffExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            const string target = "nsff";
            InvalidParameterException.ThrowIfAny(Llff.LensRefusal(scene.Lens, target), Llff.CameraRefusal(scene.Intrinsics, target));
            var videos = FlowExportInput.Videos(scene, target, out var record);
            FlowExportInput.RequireConsecutivePairs(record, videos, target);
            if (!record.SceneFlow)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(FlowLayout.RecordFile, "sceneFlow false",
                        "has no scene flow, and --to nsff writes motion_masks/ from it (255 where the point moves).",
                        "Delete flow/ (written by nerf-dataset flow) and run nerf-dataset flow <dataset> again without --no-scene-flow."),
                });
            var bounds = videos.Select(v => DepthBounds.Of(scene, v.Frames, target, warnings)).ToList();
            outDir = Path.GetFullPath(outDir);
            var recordFile = Path.Combine(outDir, Nsff.RecordFileName);
            DatasetConverter.EnsureAbsent(recordFile);
            foreach (var v in videos) DatasetConverter.EnsureAbsent(Path.Combine(outDir, v.Name));

            var root = scene.RootDirectory;
            var k = scene.Intrinsics;
            var background = ProtocolBackground.For(root);
            var written = new List<string>();
            var described = new JArray();
            var commands = new List<string>();
            for (var vi = 0; vi < videos.Count; vi++)
            {
                var video = videos[vi];
                var folder = Path.Combine(outDir, video.Name);
                var n = video.Frames.Count;
                var poses = new double[n * 17];
                for (var t = 0; t < n; t++)
                {
                    Array.Copy(Llff.Row(video.Frames[t].CameraToWorld, k.Height, k.Width, k.FlX, bounds[vi][t].Near, bounds[vi][t].Far), 0, poses, 17 * t, 17);
                    var stem = Nsff.Stem(t);
                    foreach (var images in new[] { Nsff.ImagesFolder, Nsff.SizedImagesFolder(k.Width, k.Height) })
                    {
                        var to = Path.Combine(folder, images, stem + ".png");
                        ExportRgb.Write(root, video.Frames[t].ImagePath, to, (background.R, background.G, background.B), staged);
                        written.Add(to);
                    }
                    Put(staged, written, Path.Combine(folder, Nsff.DispFolder, stem + ".npy"), NumpyFiles.Float32Array(Disparity(scene, video.Frames[t]), k.Height, k.Width));
                    Put(staged, written, Path.Combine(folder, Nsff.MotionMasksFolder, stem + ".png"), PngWriter.Encode(MotionMask(root, video, k, t), k.Width, k.Height, PngPixelFormat.Gray8));
                    foreach (var forward in new[] { true, false })
                    {
                        var other = forward ? t + 1 : t - 1;
                        if (other < 0 || other >= n) continue;
                        Put(staged, written, Path.Combine(folder, Nsff.FlowFile(t, forward).Replace('/', Path.DirectorySeparatorChar)), FlowNpz(root, new FlowPair(video.Name, t, other), k));
                    }
                }
                Put(staged, written, Path.Combine(folder, Llff.PosesBoundsFileName), NumpyFiles.Float64Matrix(poses, n, 17));
                described.Add(new JObject
                {
                    ["folder"] = video.Name,
                    ["split"] = video.Record.Split,
                    ["camera_id"] = video.Record.CameraId.HasValue ? (JToken)video.Record.CameraId.Value : JValue.CreateNull(),
                    ["frames"] = new JArray(video.Record.Frames.Select(f => (object)f.Image).ToArray()),
                });
                commands.Add("NSFF (nsff_exp): python run_nerf.py --config configs/config_kid-running.txt --datadir " + folder + " --expname " + video.Name +
                             " --final_height " + k.Height + " --start_frame 0 --end_frame " + n + " --target_idx " + Math.Min(Nsff.DefaultTargetIdx, n - 1));
            }
            staged.WriteNewText(recordFile, Record(described, background.Name).ToString(Formatting.Indented) + "\n");
            written.Add(recordFile);
            return new ConversionResult(outDir, Path.Combine(outDir, videos[0].Name), written, warnings, commands);
        }

        /// <summary>1 / z per pixel (z from the 16-bit depth PNG in steps of the dataset's depth unit), 0 where the PNG is 0 (no surface).</summary>
        static float[] Disparity(ExportScene scene, ExportFrame frame)
        {
            var depth = PngGray16Reader.Read(Path.Combine(scene.RootDirectory, frame.DepthPath), out var w, out var h);
            if (w != scene.Intrinsics.Width || h != scene.Intrinsics.Height)
                throw new InvalidParameterException(new[] { new ValidationProblem("depth", frame.DepthPath, "is " + w + " × " + h + ", not the images' " + scene.Intrinsics.Width + " × " + scene.Intrinsics.Height + ".", "Re-capture the dataset.") });
            var disp = new float[depth.Length];
            for (var i = 0; i < depth.Length; i++) disp[i] = depth[i] == 0 ? 0f : (float)(1.0 / (depth[i] * scene.DepthUnitScale));
            return disp;
        }

        /// <summary>255 where the pixel's point has non-zero scene flow to the previous or the next frame.</summary>
        internal static byte[] MotionMask(string root, FlowExportVideo video, CameraIntrinsics k, int t)
        {
            var mask = new byte[k.Width * k.Height];
            foreach (var other in new[] { t - 1, t + 1 })
            {
                if (other < 0 || other >= video.Frames.Count) continue;
                var moving = FlowExportInput.Moving(root, new FlowPair(video.Name, t, other), k);
                for (var i = 0; i < mask.Length; i++) if (moving[i]) mask[i] = 255;
            }
            return mask;
        }

        /// <summary>The npz of one pair: <c>flow</c> (H, W, 2) float32 (dx, dy), 0 where NaN; <c>mask</c> (H, W) uint8, 1 = visible at the other frame.</summary>
        internal static byte[] FlowNpz(string root, FlowPair pair, CameraIntrinsics k)
        {
            var flow = FlowExportInput.Flow(root, pair, k);
            var occluded = FlowExportInput.Mask(root, pair.OccludedFile, k);
            var outside = FlowExportInput.Mask(root, pair.OutsideFile, k);
            var mask = new byte[occluded.Length];
            var values = new float[flow.Length];
            for (var p = 0; p < mask.Length; p++)
            {
                float dx = flow[2 * p], dy = flow[2 * p + 1];
                if (float.IsNaN(dx) || float.IsNaN(dy)) continue;
                values[2 * p] = dx;
                values[2 * p + 1] = dy;
                mask[p] = (byte)(occluded[p] || outside[p] ? 0 : 1);
            }
            return NumpyFiles.Npz(new[]
            {
                new KeyValuePair<string, byte[]>("flow", NumpyFiles.Float32Array(values, k.Height, k.Width, 2)),
                new KeyValuePair<string, byte[]>("mask", NumpyFiles.UInt8Array(mask, k.Height, k.Width)),
            });
        }

        static JObject Record(JArray scenes, string background) => new JObject
        {
            ["format"] = "nerf-dataset-nsff",
            ["source"] = FlowLayout.RecordFile,
            ["files"] = new JObject
            {
                ["images/%05d.png"] = "frame t's image, RGB over the " + background + " background; images_<W>x<H>/ holds the same images for --final_height H",
                ["poses_bounds.npy"] = "LLFF rows: [down, right, back | centre | H W focal] and each view's near and far depth from its depth map",
                ["disp/%05d.npy"] = "(H, W) float32 exact disparity 1 / z (output units), 0 where there is no surface",
                ["motion_masks/%05d.png"] = "255 where the pixel's point moves to frame t - 1 or t + 1 (scene flow not 0), else 0",
                ["flow_i1/%05d_fwd.npz"] = "flow (H, W, 2) float32 (dx, dy) pixels from frame t to t + 1, 0 where there is no flow; mask (H, W) uint8 1 = visible at t + 1",
                ["flow_i1/%05d_bwd.npz"] = "the same from frame t to t - 1 (NSFF's direction: the negative of Kubric's backward flow)",
                ["target_only"] = "only the target's surface has flow; scenery outside the target is static in the masks and has mask 0",
            },
            ["scenes"] = scenes,
        };

        static void Put(StagedOutput staged, List<string> written, string path, byte[] bytes)
        {
            staged.WriteNewBytes(path, bytes);
            written.Add(path);
        }
    }
}
