using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame time keys of the transforms files. <c>time</c> is the one the loaders read (in [0, 1]):
    /// D-NeRF's load_blender.py line 96 (<c>frame['time']</c>, and line 99 asserts each split's first frame is at 0),
    /// 4DGaussians' scene/dataset_readers.py line 271 (<c>mapper[frame["time"]]</c>, the mapper of lines 298–312
    /// dividing by the largest train/test time, which is 1 here) and nerfstudio's dnerf_dataparser.py line 75
    /// (<c>times.append(frame["time"])</c>, used as is). The others are this plugin's and every loader ignores them.
    /// </summary>
    public static class TimeKeys
    {
        /// <summary>A dynamic view's time keys in a transforms frame; nothing for a static view.</summary>
        internal static void WriteFrame(TransformsFramesText frame, PlannedView v)
        {
            if (!v.Time.HasValue) return;
            var time = v.Time.Value;
            frame.NumberKey(Time, time.Normalised);
            frame.NumberKey(Seconds, time.Seconds);
            if (time.Camera < 0) return;
            frame.IntegerKey(Step, time.Step);
            frame.IntegerKey(Camera, time.Camera);
        }

        public const string Time = "time";
        public const string Seconds = "time_seconds";
        public const string Step = "time_step";
        public const string Camera = "camera_id"; // written with the others by TransformsFramesText

        /// <summary>Reads a frame's time keys (<see cref="DatasetFolder"/> calls it for every frame); <see cref="FrameTime.None"/> when it has none.</summary>
        public static FrameTime Read(JObject frame)
        {
            if (frame == null) return FrameTime.None;
            var time = frame[Time];
            var seconds = frame[Seconds];
            var step = frame[Step];
            var camera = frame[Camera];
            if (time == null && seconds == null && step == null && camera == null) return FrameTime.None;
            return new FrameTime
            {
                HasTime = time != null,
                Time = JsonValues.TryNumber(time, out var t) ? t : (double?)null,
                HasSeconds = seconds != null,
                Seconds = JsonValues.TryNumber(seconds, out var s) ? s : (double?)null,
                Step = JsonValues.TryInt(step, out var k) ? k : (int?)null,
                Camera = JsonValues.TryInt(camera, out var c) ? c : (int?)null,
                StepText = step?.ToString(),
                CameraText = camera?.ToString(),
            };
        }
    }
}
