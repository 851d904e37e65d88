using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One mesh of the geometry pack as dataset_config.json records it.</summary>
    public sealed class GeometryPackEntry
    {
        /// <summary>The time step (the views' <c>time_step</c>); null for a static capture's mesh.</summary>
        public int? Step { get; internal set; }

        /// <summary>The normalised time (the views' <c>time</c> key, in [0, 1]); null for a static capture's mesh.</summary>
        public double? Time { get; internal set; }

        public double? Seconds { get; internal set; }

        /// <summary>Relative to the dataset, '/' separated.</summary>
        public string File { get; internal set; }

        public string Sha256 { get; internal set; }
        public long Triangles { get; internal set; }

        /// <summary>What is wrong with the record's numbers (a <c>step</c> of 1e11), naming the key; null when nothing is.</summary>
        public string Problem { get; internal set; }
    }

    /// <summary>
    /// The per-step record of <c>"geometryPack": "everyStep"</c>, under dataset_config.json's <c>geometry</c>:
    /// <c>{"everyStep": true, "frame": …, "steps": [{"step", "time", "time_seconds", "file", "sha256", "vertices",
    /// "triangles", "objects"}…]}</c>, one entry per time step in step order; and <see cref="Entries"/>, which reads either
    /// kind of record (a single mesh is one entry).
    /// </summary>
    public static class GeometryPackStepRecord
    {
        public const string StepsKey = "steps";
        public const string EveryStepKey = "everyStep";

        public static void AddTime(JObject json, ViewTime time)
        {
            json["step"] = time.Step;
            json[TimeKeys.Time] = time.Normalised;
            json[TimeKeys.Seconds] = time.Seconds;
        }

        /// <summary>Step <paramref name="time"/>.Step's entry: its time first, then what <see cref="GeometryPackRecord.ToJson(IReadOnlyList{SurfaceMesh}, string)"/> says of a mesh.</summary>
        public static JObject StepJson(ViewTime time, IReadOnlyList<SurfaceMesh> outputMeshes, string sha256)
        {
            var entry = new JObject();
            AddTime(entry, time);
            var mesh = GeometryPackRecord.ToJson(outputMeshes, sha256);
            mesh.Remove("frame");
            mesh["file"] = GeometryPackSteps.RelativePath(time.Step);
            foreach (var property in mesh.Properties()) entry[property.Name] = property.Value;
            return entry;
        }

        public static JObject ToJson(IReadOnlyList<JObject> steps) => new JObject
        {
            [EveryStepKey] = true,
            ["frame"] = GeometryPackRecord.FrameText,
            ["triangles"] = steps.Sum(s => (long)s["triangles"]),
            [StepsKey] = new JArray(steps),
        };

        /// <summary>Whether the config records a per-step pack.</summary>
        public static bool IsPerStep(JObject config) => config?[GeometryPackRecord.Key] is JObject g && g[StepsKey] is JArray;

        /// <summary>
        /// Every mesh the config records, in step order: the per-step entries, or the single mesh (with its step and time
        /// when the capture was dynamic). Empty when there is no record; entries without a file name are left out.
        /// </summary>
        public static IReadOnlyList<GeometryPackEntry> Entries(JObject config)
        {
            var result = new List<GeometryPackEntry>();
            if (!(config?[GeometryPackRecord.Key] is JObject geometry)) return result;
            if (geometry[StepsKey] is JArray steps)
            {
                foreach (var item in steps.OfType<JObject>())
                    if (Read(item) is GeometryPackEntry e) result.Add(e);
            }
            else if (Read(geometry) is GeometryPackEntry single) result.Add(single);
            return result.OrderBy(e => e.Step ?? -1).ToList();
        }

        static GeometryPackEntry Read(JObject item)
        {
            if (item["file"]?.Type != JTokenType.String) return null;
            // Through JsonValues: a step of 1e11 or a 30-digit triangle count is a problem naming the key, not an OverflowException.
            var entry = new GeometryPackEntry
            {
                File = (string)item["file"],
                Sha256 = item["sha256"]?.Type == JTokenType.String ? (string)item["sha256"] : null,
                Triangles = JsonValues.TryLong(item["triangles"], out var triangles) ? triangles : 0,
                Time = JsonValues.TryNumber(item[TimeKeys.Time], out var t) ? (double?)t : null,
                Seconds = JsonValues.TryNumber(item[TimeKeys.Seconds], out var s) ? (double?)s : null,
            };
            var step = item["step"];
            if (step != null && step.Type != JTokenType.Null)
            {
                if (JsonValues.TryInt(step, out var k) && k >= 0) entry.Step = k;
                else entry.Problem = "geometry step = " + step.ToString(Newtonsoft.Json.Formatting.None) + " (" + entry.File + ") is not a whole number from 0 to " + int.MaxValue + ".";
            }
            return entry;
        }
    }
}
