using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// DyCheck's <c>covisible/</c> and <c>keypoint/</c> (docs/DATASETS.md; read by datasets/nerfies.py:204–311), written
    /// exactly from the dataset's flow/ when it has one (<see cref="FlowRecord"/>); without flow/ both are left out with a
    /// warning (DyCheck runs without them: nerfies.py:575–581, and kp_transfer only when <c>keypoint/</c> exists, nerfies.py:616–617).
    /// <list type="bullet">
    /// <item><c>covisible/1x/val/&lt;id&gt;.png</c> (0/255) for every val view: a pixel is co-visible unless at most
    /// max(5, ⌊S/10⌋) of the S training images see its surface point (tools/process_covisible.py:49–50, 152–158, which
    /// finds it with RAFT; here each point is followed on the geometry pack's meshes into every train view at its time
    /// step and tested for occlusion, as flow/ is made). Pixels off the target are written co-visible: only the target's
    /// surface is in the geometry pack.</item>
    /// <item><c>keypoint/1x/train/&lt;id&gt;.json</c> for DyCheck's 10 strided train frames (kp_transfer.py:37–48,
    /// utils/common.py:148–156): the first tracks file's points, (x, y, v) with x, y the pixel index (the reader adds 0.5,
    /// nerfies.py:282, 309–311) and invisible rows (0, 0, 0) (nerfies.py:301); and <c>skeleton.json</c>, an unconnected
    /// skeleton (load_skeleton, nerfies.py:313–336; visuals/kps/skeleton.py:37–66). Only for a single-camera train split
    /// of at least 10 frames: kp_transfer draws frames from the whole split, and our tracks follow one camera.</item>
    /// </list>
    /// </summary>
    public static class DyCheckFlowFiles
    {
        public const string CovisibleFolder = "covisible";
        public const string KeypointFolder = "keypoint";

        /// <summary>tools/process_covisible.py's defaults: num_min_frames 5, min_frame_ratio 0.1 (lines 49–50).</summary>
        public const int MinFrames = 5;

        public static IReadOnlyList<string> Write(ExportScene scene, IReadOnlyList<NerfiesView> views, string outDir, StagedOutput staged, List<ValidationProblem> warnings)
        {
            var written = new List<string>();
            var record = FlowRecord.Read(scene.RootDirectory);
            if (record == null)
            {
                warnings.Add(new ValidationProblem("flow", FlowLayout.RecordFile,
                    "is missing, so covisible/ and keypoint/ are not written (DyCheck evaluates without them).",
                    "For exact co-visibility masks and keypoints, run nerf-dataset flow <dataset> --tracks 0 first."));
                return written;
            }
            foreach (var path in new[] { Path.Combine(outDir, CovisibleFolder), Path.Combine(outDir, KeypointFolder) })
                DatasetConverter.EnsureAbsent(path);
            var train = views.Where(v => v.Train).ToList();
            var val = views.Where(v => !v.Train).ToList();
            if (val.Count > 0) written.AddRange(Covisible(scene, record, train, val, outDir, staged));
            written.AddRange(Keypoints(scene.RootDirectory, record, train, outDir, staged, warnings));
            return written;
        }

        /// <summary>The co-visibility threshold: co-visible when more than this many of <paramref name="trainCount"/> training images see the point.</summary>
        public static int Threshold(int trainCount) => Math.Max(MinFrames, (int)(0.1 * trainCount));

        static IEnumerable<string> Covisible(ExportScene scene, FlowRecord record, IReadOnlyList<NerfiesView> train, IReadOnlyList<NerfiesView> val, string outDir, StagedOutput staged)
        {
            var root = scene.RootDirectory;
            var config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            var videos = FlowVideos.Of(scene, GeometryPackStepRecord.Entries(config?.Json));
            var meshes = FlowMeshes.Read(root, videos);
            var steps = new Dictionary<string, int>();
            foreach (var v in record.Videos)
                foreach (var f in v.Frames)
                    steps[f.Image] = f.Step;
            // A val view shares its time id with train views (DyCheck indexes frames by time id and camera id), so it is at
            // their step; a monocular capture's test views are in no video of flow/ but sit at a train view's time.
            var trainStep = new Dictionary<int, int>();
            foreach (var t in train)
                if (steps.TryGetValue(t.Frame.ImagePath.Replace('\\', '/'), out var s)) trainStep[t.TimeId] = s;
            int StepOf(NerfiesView v) => steps.TryGetValue(v.Frame.ImagePath.Replace('\\', '/'), out var s) ? s
                : trainStep.TryGetValue(v.TimeId, out s) ? s
                : throw NerfiesViews.Refuse("flow", v.Frame.ImagePath, "is in no video of " + FlowLayout.RecordFile + ", so its co-visibility cannot be followed.", "Compute flow again for this dataset (nerf-dataset flow).");
            var k = scene.Intrinsics;
            FlowCamera Camera(NerfiesView v) => new FlowCamera(v.Frame.CameraToWorld, k.FlX, k.FlY, k.Cx, k.Cy, k.Width, k.Height);
            var threshold = Threshold(train.Count);
            var folder = Path.Combine(outDir, CovisibleFolder, Nerfies.Level(DyCheck.Factor), "val");
            foreach (var v in val)
            {
                var s = StepOf(v);
                var from = Camera(v);
                var seen = new int[k.Width * k.Height];
                byte[] state = null;
                foreach (var t in train)
                {
                    var st = StepOf(t);
                    var field = new SurfaceFlow(meshes.Vertices(s), meshes.Tree(s), meshes.Vertices(st), meshes.Tree(st), meshes.Triangles).Image(from, Camera(t));
                    state = field.State;
                    for (var p = 0; p < seen.Length; p++)
                        if (field.State[p] == (byte)FlowState.Visible) seen[p]++;
                }
                var mask = new byte[seen.Length];
                for (var p = 0; p < mask.Length; p++)
                    mask[p] = state[p] == (byte)FlowState.NoSurface || seen[p] > threshold ? (byte)255 : (byte)0;
                var file = Path.Combine(folder, v.Id + ".png");
                staged.WriteNewBytes(file, PngWriter.Encode(mask, k.Width, k.Height, PngPixelFormat.Gray8));
                yield return file;
            }
        }

        static IEnumerable<string> Keypoints(string root, FlowRecord record, IReadOnlyList<NerfiesView> train, string outDir, StagedOutput staged, List<ValidationProblem> warnings)
        {
            var video = record.Videos.FirstOrDefault(v => v.Split == "train" && train.All(t => ShapeOfMotion.PositionOf(v, t.Frame) >= 0));
            var tracks = video == null ? null : record.Tracks.FirstOrDefault(t => t.Video == video.Name);
            string why = video == null ? "the train split holds several cameras, and DyCheck's keypoint frames are drawn from the whole split while our tracks follow one camera"
                : tracks == null ? "flow/ has no tracks of the train video"
                : train.Count < ShapeOfMotion.KeypointFrames ? "the train split has " + train.Count + " frames, fewer than the " + ShapeOfMotion.KeypointFrames + " keypoint frames DyCheck draws (kp_transfer.py:37–48; common.strided_subset refuses more than the split holds)"
                : null;
            if (why != null)
            {
                warnings.Add(new ValidationProblem("keypoint", KeypointFolder + "/", "is not written: " + why + ".",
                    "For keypoints, capture monocular with at least 10 train frames and compute flow with tracks (nerf-dataset flow <dataset> --tracks 0)."));
                yield break;
            }
            var file = FlowTracksFile.Read(ShapeOfMotion.Full(root, tracks.File));
            var folder = Path.Combine(outDir, KeypointFolder, Nerfies.Level(DyCheck.Factor), "train");
            foreach (var i in ShapeOfMotion.StridedSubset(train.Count, ShapeOfMotion.KeypointFrames))
            {
                var path = Path.Combine(folder, train[i].Id + ".json");
                staged.WriteNewText(path, ShapeOfMotionExport.KeypointJson(ShapeOfMotion.KeypointRows(file, ShapeOfMotion.PositionOf(video, train[i].Frame), 1.0)));
                yield return path;
            }
            var skeleton = Path.Combine(folder, "skeleton.json");
            staged.WriteNewText(skeleton, ExportJson.Serialise(Skeleton(file.Points)));
            yield return skeleton;
        }

        /// <summary>An unconnected skeleton of <paramref name="count"/> keypoints: no parents, anonymous names, one colour.</summary>
        public static JObject Skeleton(int count) => new JObject
        {
            ["name"] = "unconnected",
            ["parents"] = new JArray(Enumerable.Repeat<object>(null, count).Select(_ => JValue.CreateNull())),
            ["kp_names"] = new JArray(Enumerable.Repeat("ANONYMOUS KP", count)),
            ["palette"] = new JArray(Enumerable.Range(0, count).Select(_ => new JArray(255, 0, 0))),
        };
    }
}
