using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A split's <c>"source"</c> object in a config file, written only when it is not the formation (so configs
    /// without imported cameras stay as they were): <c>{"kind": "imported", "path": …, "fileSplit": …, "useFileIntrinsics": …}</c>.
    /// Reading goes through <see cref="DatasetSettingsJson"/>'s reader, so errors and unknown keys are reported alike.
    /// </summary>
    static class CameraSourceJson
    {
        public static void Write(JsonWriter w, CameraSourceSettings s)
        {
            w.WritePropertyName("source");
            w.WriteStartObject();
            w.WritePropertyName("kind"); w.WriteValue(CameraSourceSettings.KindName(s.Kind));
            w.WritePropertyName("path"); w.WriteValue(s.Path ?? "");
            w.WritePropertyName("fileSplit"); w.WriteValue(s.FileSplit ?? "");
            w.WritePropertyName("useFileIntrinsics"); w.WriteValue(s.UseFileIntrinsics);
            w.WriteEndObject();
        }

        public static void Read(JToken token, string path, CameraSourceSettings s,
            Func<JToken, string, string> readString, Func<JToken, string, bool> readBool,
            Func<JToken, string, string, SettingsFormatException> error,
            Action<JToken, string, Dictionary<string, Action<JToken, string>>, string> readObject)
        {
            readObject(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["kind"] = (t, p) =>
                {
                    if (!CameraSourceSettings.TryParseKind(readString(t, p), out var kind))
                        throw error(t, p, "must be \"formation\" or \"imported\", not \"" + (string)t + "\".");
                    s.Kind = kind;
                },
                ["path"] = (t, p) => s.Path = readString(t, p),
                ["fileSplit"] = (t, p) => s.FileSplit = readString(t, p),
                ["useFileIntrinsics"] = (t, p) => s.UseFileIntrinsics = readBool(t, p),
            }, "");
        }
    }
}
