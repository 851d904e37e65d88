using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Computes a dynamic dataset's exact flow from its geometry pack and poses and writes <c>flow/</c>
    /// (<see cref="FlowLayout"/>, Documentation~/output-format.md): per frame pair of every video the flow, the
    /// occluded and outside masks and the scene flow, per query frame the tracks, and <c>flow/flow.json</c>. Writes only
    /// into a <c>flow/</c> folder that does not exist yet, and only new files.
    /// </summary>
    public static class FlowWriter
    {
        /// <param name="progress">(pairs and query frames done, all of them); may be null.</param>
        /// <param name="threads">Each image's rows and each track's frames are shared out among up to this many threads;
        /// the files are the same for any count (every pixel and point is computed alone).</param>
        /// <returns>flow.json's content (also written).</returns>
        public static JObject Write(string root, FlowSettings settings, Action<int, int> progress = null, int threads = 1)
        {
            var scene = BlenderDatasetLoader.Load(root);
            var config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            if (scene.Lens != null)
                throw Refuse("lens", "a distorted lens", "is not yet carried by flow: the flow is computed for a pinhole camera.", "Capture without a lens for flow.");
            var videos = FlowVideos.Of(scene, GeometryPackStepRecord.Entries(config?.Json));
            var folder = Path.Combine(root, FlowLayout.Folder);
            if (Directory.Exists(folder) || File.Exists(folder))
                throw Refuse("flow", folder, "exists already; flow is written only into a new folder, never over files.", "Move it away or compute flow for a copy of the dataset.");
            var meshes = FlowMeshes.Read(root, videos);
            var k = scene.Intrinsics;

            var work = videos.Select(v => (video: v, pairs: FlowPairs.Of(v.Name, v.Frames.Count, settings),
                queries: (settings.TrackQueryFrames ?? new int[0]).Where(q => q >= 0 && q < v.Frames.Count).Distinct().ToList())).ToList();
            var total = work.Sum(w => w.pairs.Count + w.queries.Count);
            var done = 0;
            var pairRecords = new JArray();
            var trackRecords = new JArray();
            FileOps.CreateDirectory(folder);
            foreach (var (video, pairs, queries) in work)
            {
                FileOps.CreateDirectory(Path.Combine(root, FlowLayout.VideoFolder(video.Name)));
                var cameras = video.Frames.Select(f => new FlowCamera(f.Frame.CameraToWorld, k.FlX, k.FlY, k.Cx, k.Cy, k.Width, k.Height)).ToList();
                foreach (var pair in pairs)
                {
                    int sa = video.Frames[pair.From].Step, sb = video.Frames[pair.To].Step;
                    var flow = new SurfaceFlow(meshes.Vertices(sa), meshes.Tree(sa), meshes.Vertices(sb), meshes.Tree(sb), meshes.Triangles);
                    var field = flow.Image(cameras[pair.From], cameras[pair.To], threads);
                    WritePair(root, pair, field, settings.SceneFlow);
                    pairRecords.Add(FlowRecord.PairJson(pair, settings.SceneFlow));
                    progress?.Invoke(++done, total);
                }
                foreach (var q in queries)
                {
                    var tracks = SurfaceTracks.Of(meshes, video, cameras, q, settings.TrackStride, threads);
                    var file = FlowLayout.TracksFile(video.Name, q);
                    FileOps.WriteNewBytes(Full(root, file), TracksNpz(tracks));
                    trackRecords.Add(FlowRecord.TracksJson(video.Name, tracks, file));
                    progress?.Invoke(++done, total);
                }
            }
            var record = FlowRecord.ToJson(videos, pairRecords, trackRecords, settings);
            FileOps.WriteNewText(Full(root, FlowLayout.RecordFile), record.ToString(Newtonsoft.Json.Formatting.Indented) + "\n");
            return record;
        }

        /// <summary>The pair's files: the flow (NaN where none), the two masks (255 = hidden / outside at the other frame), the scene flow.</summary>
        public static void WritePair(string root, FlowPair pair, FlowField field, bool sceneFlow)
        {
            int w = field.Width, h = field.Height, n = w * h;
            FileOps.WriteNewBytes(Full(root, pair.FlowFile), FloFile.Encode(field.Flow, w, h));
            var occluded = new byte[n];
            var outside = new byte[n];
            for (var p = 0; p < n; p++)
            {
                occluded[p] = field.State[p] == (byte)FlowState.Hidden ? (byte)255 : (byte)0;
                outside[p] = field.State[p] == (byte)FlowState.OutsideImage ? (byte)255 : (byte)0;
            }
            FileOps.WriteNewBytes(Full(root, pair.OccludedFile), PngWriter.Encode(occluded, w, h, PngPixelFormat.Gray8));
            FileOps.WriteNewBytes(Full(root, pair.OutsideFile), PngWriter.Encode(outside, w, h, PngPixelFormat.Gray8));
            if (!sceneFlow) return;
            // RGBA: scene flow and 1 where the pixel shows the target; 0 0 0 0 where it does not. ExrWriter takes rows bottom-up.
            var rgba = new float[4 * n];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    int p = y * w + x, o = 4 * ((h - 1 - y) * w + x);
                    if (field.State[p] == (byte)FlowState.NoSurface) continue;
                    rgba[o] = field.SceneFlow[3 * p];
                    rgba[o + 1] = field.SceneFlow[3 * p + 1];
                    rgba[o + 2] = field.SceneFlow[3 * p + 2];
                    rgba[o + 3] = 1;
                }
            FileOps.WriteNewBytes(Full(root, pair.SceneFlowFile), ExrWriter.Encode(rgba, w, h, 4));
        }

        /// <summary>The tracks as an .npz: query_xy (N, 2), xy (T, N, 2), state (T, N) uint8 (<see cref="FlowState"/>), points (T, N, 3).</summary>
        public static byte[] TracksNpz(SurfaceTracks t) => NumpyFiles.Npz(new[]
        {
            new KeyValuePair<string, byte[]>("query_xy", NumpyFiles.Float32Array(t.QueryXy, t.Points, 2)),
            new KeyValuePair<string, byte[]>("xy", NumpyFiles.Float32Array(t.Xy, t.Frames, t.Points, 2)),
            new KeyValuePair<string, byte[]>("state", NumpyFiles.UInt8Array(t.State, t.Frames, t.Points)),
            new KeyValuePair<string, byte[]>("points", NumpyFiles.Float32Array(t.Positions, t.Frames, t.Points, 3)),
        });

        static string Full(string root, string relative) => Path.Combine(root, relative.Replace('/', Path.DirectorySeparatorChar));

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
