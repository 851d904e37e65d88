using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A complete, deterministic text form of a plan (every pose at round-trip precision): two plans are the
    /// same exactly when their texts are equal, which is how determinism is tested and how a run can be diffed.
    /// </summary>
    public static class CapturePlanJson
    {
        public static string Write(CapturePlan plan)
        {
            using (var text = JsonNumbers.CreateText())
            {
                using (var w = JsonNumbers.CreateWriter(text))
                {
                    w.WriteStartObject();
                    w.WritePropertyName("distance"); JsonNumbers.Write(w, plan.Distance);
                    w.WritePropertyName("width"); w.WriteValue(plan.Intrinsics.Width);
                    w.WritePropertyName("height"); w.WriteValue(plan.Intrinsics.Height);
                    w.WritePropertyName("fl_x"); JsonNumbers.Write(w, plan.Intrinsics.FlX);
                    w.WritePropertyName("fl_y"); JsonNumbers.Write(w, plan.Intrinsics.FlY);
                    w.WritePropertyName("views");
                    w.WriteStartArray();
                    foreach (var v in plan.Views)
                    {
                        w.WriteStartObject();
                        w.WritePropertyName("split"); w.WriteValue(DatasetSplits.Name(v.Split));
                        w.WritePropertyName("index"); w.WriteValue(v.Index);
                        w.WritePropertyName("unityPosition"); Vector(w, v.Pose.Position.X, v.Pose.Position.Y, v.Pose.Position.Z);
                        w.WritePropertyName("unityRotation");
                        var q = v.Pose.Rotation;
                        w.WriteStartArray();
                        JsonNumbers.Write(w, q.X); JsonNumbers.Write(w, q.Y); JsonNumbers.Write(w, q.Z); JsonNumbers.Write(w, q.W);
                        w.WriteEndArray();
                        w.WritePropertyName("transform_matrix");
                        BlenderTransformsWriter.WriteMatrix(w, v.TransformMatrix);
                        w.WritePropertyName("files");
                        w.WriteStartArray();
                        foreach (var f in v.Files) w.WriteValue(f.RelativePath);
                        w.WriteEndArray();
                        w.WriteEndObject();
                    }
                    w.WriteEndArray();
                    w.WriteEndObject();
                }
                return text.ToString() + "\n"; // the writer's text, formatted by CreateText's invariant culture
            }
        }

        static void Vector(JsonWriter w, double x, double y, double z)
        {
            w.WriteStartArray();
            JsonNumbers.Write(w, x); JsonNumbers.Write(w, y); JsonNumbers.Write(w, z);
            w.WriteEndArray();
        }
    }
}
