using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A split's <c>"source"</c> object in a config file, written only when it is not the formation (so configs
    /// without other sources stay as they were), with the keys of its kind:
    /// <c>{"kind": "imported", "path", "fileSplit", "useFileIntrinsics"}</c>,
    /// <c>{"kind": "sceneCameras", "parent", "useCameraIntrinsics"}</c>,
    /// <c>{"kind": "animatedCamera", "camera", "useCameraIntrinsics", "samples", "frameStep", "frameRate", "start", "end"}</c>.
    /// <c>{"kind": "volume", "box", "look", "density", "jitterDegrees", "clearance"}</c>, and <c>"waypoints"</c> with look "path".
    /// Reading accepts every key whatever the kind (they are ignored by other kinds) and goes through
    /// <see cref="DatasetSettingsJson"/>'s reader, so errors and unknown keys are reported alike.
    /// </summary>
    static class CameraSourceJson
    {
        public static void Write(JsonWriter w, CameraSourceSettings s)
        {
            w.WritePropertyName("source");
            w.WriteStartObject();
            w.WritePropertyName("kind"); w.WriteValue(CameraSourceSettings.KindName(s.Kind));
            if (s.IsImported)
            {
                w.WritePropertyName("path"); w.WriteValue(s.Path ?? "");
                w.WritePropertyName("fileSplit"); w.WriteValue(s.FileSplit ?? "");
                w.WritePropertyName("useFileIntrinsics"); w.WriteValue(s.UseFileIntrinsics);
            }
            else if (s.IsFromScene)
            {
                w.WritePropertyName(s.Kind == CameraSourceKind.SceneCameras ? "parent" : "camera"); w.WriteValue(s.ObjectPath ?? "");
                w.WritePropertyName("useCameraIntrinsics"); w.WriteValue(s.UseCameraIntrinsics);
                if (s.Kind == CameraSourceKind.AnimatedCamera)
                {
                    w.WritePropertyName("samples"); w.WriteValue(s.Samples);
                    w.WritePropertyName("frameStep"); w.WriteValue(s.FrameStep);
                    JsonNumbers.Number(w, "frameRate", s.FrameRate);
                    JsonNumbers.Number(w, "start", s.Start);
                    JsonNumbers.Number(w, "end", s.End);
                }
            }
            else if (s.IsVolume)
            {
                w.WritePropertyName("box"); w.WriteValue(s.ObjectPath ?? "");
                w.WritePropertyName("look"); w.WriteValue(VolumePlanning.LookName(s.Look));
                JsonNumbers.Number(w, "density", s.Density);
                JsonNumbers.Number(w, "jitterDegrees", s.JitterDegrees);
                JsonNumbers.Number(w, "clearance", s.Clearance);
                if (s.Look == VolumeLook.Path)
                {
                    w.WritePropertyName("waypoints"); w.WriteValue(s.PathObject ?? "");
                }
            }
            w.WriteEndObject();
        }

        public static void Read(JToken token, string path, CameraSourceSettings s,
            Func<JToken, string, string> readString, Func<JToken, string, bool> readBool,
            Func<JToken, string, int> readInt, Func<JToken, string, double> readDouble,
            Func<JToken, string, string, SettingsFormatException> error,
            Action<JToken, string, Dictionary<string, Action<JToken, string>>, string> readObject)
        {
            readObject(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["kind"] = (t, p) =>
                {
                    if (!CameraSourceSettings.TryParseKind(readString(t, p), out var kind))
                        throw error(t, p, "must be \"formation\", \"imported\", \"sceneCameras\", \"animatedCamera\" or \"volume\", not \"" + (string)t + "\".");
                    s.Kind = kind;
                },
                ["path"] = (t, p) => s.Path = readString(t, p),
                ["fileSplit"] = (t, p) => s.FileSplit = readString(t, p),
                ["useFileIntrinsics"] = (t, p) => s.UseFileIntrinsics = readBool(t, p),
                ["parent"] = (t, p) => s.ObjectPath = readString(t, p),
                ["camera"] = (t, p) => s.ObjectPath = readString(t, p),
                ["useCameraIntrinsics"] = (t, p) => s.UseCameraIntrinsics = readBool(t, p),
                ["samples"] = (t, p) => s.Samples = readInt(t, p),
                ["frameStep"] = (t, p) => s.FrameStep = readInt(t, p),
                ["frameRate"] = (t, p) => s.FrameRate = readDouble(t, p),
                ["start"] = (t, p) => s.Start = readDouble(t, p),
                ["end"] = (t, p) => s.End = readDouble(t, p),
                ["box"] = (t, p) => s.ObjectPath = readString(t, p),
                ["look"] = (t, p) =>
                {
                    if (!VolumePlanning.TryParseLook(readString(t, p), out var look))
                        throw error(t, p, "must be \"ring\", \"sphere\", \"forward\" or \"path\", not \"" + (string)t + "\".");
                    s.Look = look;
                },
                ["density"] = (t, p) => s.Density = readDouble(t, p),
                ["jitterDegrees"] = (t, p) => s.JitterDegrees = readDouble(t, p),
                ["clearance"] = (t, p) => s.Clearance = readDouble(t, p),
                // Not "path": an imported source's file path has that key in the same reader.
                ["waypoints"] = (t, p) => s.PathObject = readString(t, p),
            }, "");
        }
    }
}
