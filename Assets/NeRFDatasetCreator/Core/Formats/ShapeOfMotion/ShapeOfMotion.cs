using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Shape of Motion's iPhone layout (vye16/shape-of-motion 697d462, flow3d/data/iphone_dataset.py; citations in
    /// Documentation~/maintainers/layouts-shape-of-motion.md): DyCheck's iPhone files (<see cref="DyCheckExport.WriteLayout"/>)
    /// plus <c>flow3d_preprocessed/2d_tracks/1x/{query}_{target}.npy</c> for every ordered pair of frames,
    /// <c>flow3d_preprocessed/track_anything/1x/{frame}.png</c> foreground masks and <c>keypoint/2x/train/{frame}.json</c>.
    /// A track row is (x, y, occlusion logit, expected-distance logit), float32 (iphone_dataset.py:250–261, 635–668):
    /// x, y are pixel indices — the loader samples with <c>normalize_coords</c> (x / (W − 1) · 2 − 1) and
    /// <c>align_corners=True</c> (utils.py:27–29, iphone_dataset.py:670–679), so pixel i's centre is i: our continuous
    /// coordinate − 0.5.
    /// </summary>
    public static class ShapeOfMotion
    {
        public const string FolderName = "shape-of-motion";
        public const string TracksFolder = "flow3d_preprocessed/2d_tracks/1x";
        public const string MasksFolder = "flow3d_preprocessed/track_anything/1x";
        public const string KeypointFolder = "keypoint/2x/train";

        /// <summary>
        /// The logit written for exact truth: −50 for "visible" / "certain", +50 for "occluded". The parser takes
        /// visibility = 1 − sigmoid(occlusion) and confidence = 1 − sigmoid(expected distance) and keeps a point where
        /// their product exceeds 0.5 (utils.py:53–66); e^−50 ≈ 2·10⁻²² is below half a unit in the last place of 1 in
        /// float32 and float64, so both come out exactly 0 or 1 — the parser's sigmoid saturates and no weight is lost.
        /// </summary>
        public const float SaturatedLogit = 50f;

        /// <summary>
        /// The coordinates written where a point is behind the camera (our tracks hold NaN there): one pixel left of and
        /// above the image, so the loader's mask test (<c>grid_sample</c> with zero padding, iphone_dataset.py:485–494)
        /// drops it like any other out-of-frame point; a NaN would reach the scene normalisation's mean (iphone_dataset.py:314–317).
        /// </summary>
        public const float BehindCamera = -1f;

        /// <summary>Frames the loader needs at least: its scene normalisation subsamples with step = frames // 10 (iphone_dataset.py:314–316), 0 below 10.</summary>
        public const int MinFrames = 10;

        /// <summary>DyCheck's keypoint frames: a strided subset of 10 train frames (core/tasks/kp_transfer.py:37–48).</summary>
        public const int KeypointFrames = 10;

        /// <summary>
        /// The rows of <c>{query}_{target}.npy</c>: each point of <paramref name="tracks"/> at frame
        /// <paramref name="target"/> of its video, in the file's order (row-major over the query grid, which Shape of
        /// Motion's trainer relies on: trainer.py:365–377). At the query frame itself the query pixel, as TAPIR's
        /// script writes it (preproc/compute_tracks_torch.py:151–154). Out of the image or hidden counts as occluded.
        /// </summary>
        public static float[] TrackRows(FlowTracksFile tracks, int target, bool isQuery)
        {
            var n = tracks.Points;
            var rows = new float[4 * n];
            for (var p = 0; p < n; p++)
            {
                float x, y;
                if (isQuery)
                {
                    x = tracks.QueryXy[2 * p] - 0.5f;
                    y = tracks.QueryXy[2 * p + 1] - 0.5f;
                }
                else
                {
                    x = tracks.X(target, p);
                    y = tracks.Y(target, p);
                    if (float.IsNaN(x) || float.IsNaN(y)) x = y = BehindCamera;
                    else
                    {
                        x -= 0.5f;
                        y -= 0.5f;
                    }
                }
                var visible = isQuery || tracks.StateAt(target, p) == FlowState.Visible;
                rows[4 * p] = x;
                rows[4 * p + 1] = y;
                rows[4 * p + 2] = visible ? -SaturatedLogit : SaturatedLogit;
                rows[4 * p + 3] = -SaturatedLogit;
            }
            return rows;
        }

        /// <summary>
        /// Keypoint rows (x, y, v) of frame <paramref name="frame"/>: every point of <paramref name="tracks"/>, its pixel
        /// index × <paramref name="scale"/> and v = 1 where visible; (0, 0, 0) where not, as DyCheck stores a keypoint out
        /// of view (datasets/nerfies.py:301).
        /// </summary>
        public static float[,] KeypointRows(FlowTracksFile tracks, int frame, double scale)
        {
            var rows = new float[tracks.Points, 3];
            for (var p = 0; p < tracks.Points; p++)
            {
                if (tracks.StateAt(frame, p) != FlowState.Visible) continue;
                rows[p, 0] = (float)((tracks.X(frame, p) - 0.5) * scale);
                rows[p, 1] = (float)((tracks.Y(frame, p) - 0.5) * scale);
                rows[p, 2] = 1;
            }
            return rows;
        }

        /// <summary>Positions DyCheck's <c>common.strided_subset</c> keeps: <c>np.linspace(0, n, count, endpoint=False).astype(int)</c> (utils/common.py:148–156).</summary>
        public static int[] StridedSubset(int n, int count)
        {
            var step = (double)n / count;
            return Enumerable.Range(0, count).Select(i => (int)(i * step)).ToArray();
        }

        /// <summary>
        /// The target's pixels in frame <paramref name="position"/> of <paramref name="video"/> (255) from a flow pair
        /// that starts there: a pixel shows the target exactly when it has flow or one of its masks is set (flow.json's
        /// "no_flow" and "visible" conventions). Null when no pair starts at the frame.
        /// </summary>
        public static byte[] TargetMask(string root, FlowRecord record, string video, int position, out int width, out int height)
        {
            width = height = 0;
            var pair = record.Pairs.FirstOrDefault(p => p.Video == video && p.From == position);
            if (pair == null) return null;
            var flow = FloFile.Read(Full(root, pair.FlowFile), out width, out height);
            var occluded = PngReader.Read(Full(root, pair.OccludedFile)).Samples;
            var outside = PngReader.Read(Full(root, pair.OutsideFile)).Samples;
            var mask = new byte[width * height];
            for (var p = 0; p < mask.Length; p++)
                if (!float.IsNaN(flow[2 * p]) || occluded[p] != 0 || outside[p] != 0) mask[p] = 255;
            return mask;
        }

        /// <summary>The position of <paramref name="frame"/> in <paramref name="video"/> (matched by image path), or −1.</summary>
        public static int PositionOf(FlowRecordVideo video, ExportFrame frame)
        {
            for (var i = 0; i < video.Frames.Count; i++)
                if (string.Equals(video.Frames[i].Image, frame.ImagePath.Replace('\\', '/'), StringComparison.Ordinal)) return i;
            return -1;
        }

        /// <summary>The dataset's flow record, or a refusal naming the fix when it has none.</summary>
        public static FlowRecord Require(string root, string target)
        {
            var record = FlowRecord.Read(root);
            if (record == null)
                throw NerfiesViews.Refuse("flow", FlowLayout.RecordFile,
                    "is missing: --to " + target + " writes the exact tracks of flow/, and this dataset has none.",
                    "Run nerf-dataset flow <dataset> --tracks <frames> (or capture with the \"flow\" settings section, tracks.queryFrames listing the frames), then convert again.");
            return record;
        }

        internal static string Full(string root, string relative) => Path.Combine(root, relative.Replace('/', Path.DirectorySeparatorChar));
    }
}
