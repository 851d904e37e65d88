using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>flow/flow.json</c>: what the flow folder holds and how to read it — the conventions in words, the videos (name,
    /// split, camera, frames with their image and step), every pair's files and every tracks file. <see cref="Read"/>
    /// gives it back typed, for check, convert and evaluate.
    /// </summary>
    public sealed class FlowRecord
    {
        public const string Format = "nerf-dataset-flow";
        public const int Version = 1;

        public IReadOnlyList<FlowRecordVideo> Videos { get; private set; }
        public IReadOnlyList<FlowPair> Pairs { get; private set; }
        public IReadOnlyList<FlowRecordTracks> Tracks { get; private set; }
        public bool SceneFlow { get; private set; }
        public JObject Json { get; private set; }

        public FlowRecordVideo Video(string name) => Videos.FirstOrDefault(v => v.Name == name);

        internal static JObject ToJson(IReadOnlyList<FlowVideo> videos, JArray pairs, JArray tracks, FlowSettings settings) => new JObject
        {
            ["format"] = Format,
            ["version"] = Version,
            ["conventions"] = new JObject
            {
                ["flow"] = "flow_<a>_<b>.flo (Middlebury .flo): per pixel of frame a, (dx, dy) in pixels from its centre (u + 0.5, v + 0.5) to where the same surface point projects in frame b; x to the right, y down the rows",
                ["no_flow"] = "NaN: the pixel shows no target surface, or the point is behind frame b's camera",
                ["occluded"] = "occluded_<a>_<b>.png: 255 where the point projects inside frame b's image but another part of the target is in front of it there",
                ["outside"] = "outside_<a>_<b>.png: 255 where the point projects outside frame b's image or lies behind its camera",
                ["visible"] = "a pixel with flow whose occluded and outside masks are both 0",
                ["scene_flow"] = "scene_flow_<a>_<b>.exr: RGB = the point's motion from a to b in output units, output frame (Blender, +Z up); A = 1 on the target, 0 (and RGB 0) elsewhere",
                ["occlusion_test"] = "hidden when the segment from frame b's camera to the point meets the target's mesh at b before 1 - hidden_tolerance of its length",
                ["hidden_tolerance"] = SurfaceFlow.HiddenTolerance,
                ["tracks"] = "tracks_<q>.npz: query_xy (N, 2) pixel centres (i*stride + 0.5, j*stride + 0.5) of frame q that show the target; xy (T, N, 2) where each is in every frame of the video (NaN behind the camera); state (T, N) uint8 1 visible, 2 occluded, 3 outside; points (T, N, 3) the surface point, output frame",
                ["target_only"] = "only the target's mesh moves and occludes: scenery outside the target neither has flow nor hides it",
            },
            ["videos"] = new JArray(videos.Select(v => new JObject
            {
                ["name"] = v.Name,
                ["split"] = v.Split,
                ["camera_id"] = v.CameraId.HasValue ? (JToken)v.CameraId.Value : JValue.CreateNull(),
                ["frames"] = new JArray(v.Frames.Select(f => new JObject
                {
                    ["image"] = f.Frame.ImagePath,
                    ["step"] = f.Step,
                    ["time"] = f.Frame.Time.HasValue ? (JToken)f.Frame.Time.Value : JValue.CreateNull(),
                    ["mesh"] = f.MeshFile,
                })),
            })),
            ["pairs"] = pairs,
            ["tracks"] = tracks,
            ["settings"] = new JObject
            {
                ["forward"] = settings.Forward,
                ["backward"] = settings.Backward,
                ["spans"] = new JArray(settings.Spans ?? new int[0]),
                ["sceneFlow"] = settings.SceneFlow,
                ["trackQueryFrames"] = new JArray(settings.TrackQueryFrames ?? new int[0]),
                ["trackStride"] = settings.TrackStride,
            },
        };

        internal static JObject PairJson(FlowPair pair, bool sceneFlow) => new JObject
        {
            ["video"] = pair.Video,
            ["from"] = pair.From,
            ["to"] = pair.To,
            ["direction"] = pair.Forward ? "forward" : "backward",
            ["span"] = pair.Span,
            ["flow"] = pair.FlowFile,
            ["occluded"] = pair.OccludedFile,
            ["outside"] = pair.OutsideFile,
            ["scene_flow"] = sceneFlow ? (JToken)pair.SceneFlowFile : JValue.CreateNull(),
        };

        internal static JObject TracksJson(string video, SurfaceTracks tracks, string file) => new JObject
        {
            ["video"] = video,
            ["query_frame"] = tracks.QueryFrame,
            ["stride"] = tracks.Stride,
            ["points"] = tracks.Points,
            ["frames"] = tracks.Frames,
            ["file"] = file,
        };

        /// <summary>The dataset's flow record, or null when it has no <c>flow/flow.json</c>; a malformed one is an <see cref="InvalidDataException"/> naming the key.</summary>
        public static FlowRecord Read(string root)
        {
            var path = Path.Combine(root, FlowLayout.RecordFile.Replace('/', Path.DirectorySeparatorChar));
            if (!File.Exists(path)) return null;
            JObject json;
            try { json = JObject.Parse(File.ReadAllText(path)); }
            catch (Newtonsoft.Json.JsonException e) { throw new InvalidDataException(FlowLayout.RecordFile + " is not a JSON object: " + e.Message); }
            if ((string)json["format"] != Format) throw new InvalidDataException(FlowLayout.RecordFile + ": format is not \"" + Format + "\".");
            var videos = new List<FlowRecordVideo>();
            foreach (var v in Array(json, "videos"))
                videos.Add(new FlowRecordVideo((string)v["name"], (string)v["split"], v["camera_id"]?.Type == JTokenType.Integer ? (int?)(int)v["camera_id"] : null,
                    Array(v, "frames").Select(f => new FlowRecordFrame((string)f["image"], (int)f["step"], f["time"]?.Type == JTokenType.Float || f["time"]?.Type == JTokenType.Integer ? (double?)(double)f["time"] : null, (string)f["mesh"])).ToList()));
            var pairs = Array(json, "pairs").Select(p => new FlowPair((string)p["video"], (int)p["from"], (int)p["to"])).ToList();
            var tracks = Array(json, "tracks").Select(t => new FlowRecordTracks((string)t["video"], (int)t["query_frame"], (int)t["stride"], (int)t["points"], (string)t["file"])).ToList();
            foreach (var p in pairs)
            {
                var video = videos.FirstOrDefault(v => v.Name == p.Video);
                if (video == null || p.From < 0 || p.To < 0 || p.From >= video.Frames.Count || p.To >= video.Frames.Count)
                    throw new InvalidDataException(FlowLayout.RecordFile + ": pair " + p.Video + " " + p.From + " → " + p.To + " names no frames of a video in the record.");
            }
            return new FlowRecord
            {
                Videos = videos, Pairs = pairs, Tracks = tracks, Json = json,
                SceneFlow = json["settings"]?["sceneFlow"]?.Type == JTokenType.Boolean && (bool)json["settings"]["sceneFlow"],
            };
        }

        static IEnumerable<JObject> Array(JToken json, string key) =>
            json[key] is JArray a ? a.OfType<JObject>() : throw new InvalidDataException(FlowLayout.RecordFile + ": \"" + key + "\" is not a list.");
    }

    public sealed class FlowRecordFrame
    {
        public FlowRecordFrame(string image, int step, double? time, string mesh)
        {
            Image = image;
            Step = step;
            Time = time;
            Mesh = mesh;
        }

        /// <summary>The view's image, relative to the dataset (<c>train/r_3.png</c>).</summary>
        public string Image { get; }
        public int Step { get; }
        public double? Time { get; }
        public string Mesh { get; }
    }

    public sealed class FlowRecordVideo
    {
        public FlowRecordVideo(string name, string split, int? cameraId, IReadOnlyList<FlowRecordFrame> frames)
        {
            Name = name;
            Split = split;
            CameraId = cameraId;
            Frames = frames;
        }

        public string Name { get; }
        public string Split { get; }
        public int? CameraId { get; }
        public IReadOnlyList<FlowRecordFrame> Frames { get; }
    }

    public sealed class FlowRecordTracks
    {
        public FlowRecordTracks(string video, int queryFrame, int stride, int points, string file)
        {
            Video = video;
            QueryFrame = queryFrame;
            Stride = stride;
            Points = points;
            File = file;
        }

        public string Video { get; }
        public int QueryFrame { get; }
        public int Stride { get; }
        public int Points { get; }
        public string File { get; }
    }
}
