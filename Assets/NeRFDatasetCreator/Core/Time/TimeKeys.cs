using Newtonsoft.Json;

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
        public const string Time = "time";
        public const string Seconds = "time_seconds";
        public const string Step = "time_step";
        public const string Camera = "camera_id";

        /// <summary>Writes a frame's time keys (after its transform_matrix): time and time_seconds, plus time_step and camera_id in multi-view.</summary>
        public static void Write(JsonWriter w, ViewTime time)
        {
            w.WritePropertyName(Time);
            JsonNumbers.Write(w, time.Normalised);
            w.WritePropertyName(Seconds);
            JsonNumbers.Write(w, time.Seconds);
            if (time.Camera >= 0)
            {
                w.WritePropertyName(Step); w.WriteValue(time.Step);
                w.WritePropertyName(Camera); w.WriteValue(time.Camera);
            }
        }
    }
}
