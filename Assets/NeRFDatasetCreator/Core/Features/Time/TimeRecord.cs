using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>time</c> object of dataset_config.json: how the dataset's times were made, so it can be re-rendered and
    /// its <c>time</c> keys turned back into content time (seconds = start + time · (end − start)).
    /// </summary>
    public static class TimeRecord
    {
        public const string Key = "time";

        public static void Write(JsonWriter w, TimeRange range, TimeSettings requested)
        {
            w.WriteStartObject();
            w.WritePropertyName("mode"); w.WriteValue(TimeModes.Name(range.Mode));
            w.WritePropertyName("sources");
            w.WriteStartArray();
            foreach (var name in TimeSourceNames.NamesOf(range.Sources)) w.WriteValue(name);
            w.WriteEndArray();
            JsonNumbers.Number(w, "startSeconds", range.StartSeconds);
            JsonNumbers.Number(w, "endSeconds", range.EndSeconds);
            w.WritePropertyName("endFrom"); w.WriteValue(requested.EndAtClipLength ? "clip" : "settings");
            w.WritePropertyName("steps"); w.WriteValue(range.Steps);
            w.WritePropertyName("fps");
            if (range.Fps > 0) JsonNumbers.Write(w, range.Fps);
            else w.WriteNull();
            w.WritePropertyName("mapping");
            w.WriteValue("time = (time_seconds - startSeconds) / (endSeconds - startSeconds); step k at time k / (steps - 1)" +
                         (range.Mode == TimeMode.Monocular
                             ? "; train view i at step i; val/test view 0 at time 0, the others halfway between two train steps"
                             : "; frame r_(k * cameras + c) is camera c at step k"));
            w.WriteEndObject();
        }
    }
}
