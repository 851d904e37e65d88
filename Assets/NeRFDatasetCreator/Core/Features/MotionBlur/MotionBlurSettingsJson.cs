using System;
using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>The config-file form of <see cref="MotionBlurSettings"/>, the <c>"motionBlur"</c> object; written only when on, so other configs keep their shape.</summary>
    public static class MotionBlurSettingsJson
    {
        public const string Key = "motionBlur";

        /// <summary>The <c>"motionBlur"</c> section when blur is on; nothing when it is off.</summary>
        public static void Write(JsonWriter w, MotionBlurSettings m)
        {
            if (m == null || !m.Enabled) return;
            w.WritePropertyName(Key);
            WriteObject(w, m);
        }

        public static void WriteObject(JsonWriter w, MotionBlurSettings m)
        {
            w.WriteStartObject();
            w.WritePropertyName("enabled"); w.WriteValue(m.Enabled);
            w.WritePropertyName("camera"); w.WriteValue(MotionBlurSettings.CameraName(m.Camera));
            JsonNumbers.SettingNumber(w, "shutter", m.Shutter);
            w.WritePropertyName("subFrames"); w.WriteValue(m.SubFrames);
            JsonNumbers.SettingNumber(w, "shakeDistance", m.ShakeDistance);
            JsonNumbers.SettingNumber(w, "shakeDegrees", m.ShakeDegrees);
            JsonNumbers.SettingNumber(w, "readout", m.Readout);
            w.WriteEndObject();
        }

        internal static void Read(DatasetSettingsJson.Reader reader, JToken token, string path, MotionBlurSettings m)
        {
            // A section without "enabled" is on: writing the section is asking for blur.
            var enabled = reader.Feature(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["camera"] = (v, p) => m.Camera = reader.Name<ShutterCameraMotion>(v, p, MotionBlurSettings.TryParseCamera, MotionBlurSettings.CameraNameList(), new[] { "path", "shake", "still" }),
                ["shutter"] = (v, p) => m.Shutter = reader.Double(v, p),
                ["subFrames"] = (v, p) => m.SubFrames = reader.Int(v, p),
                ["shakeDistance"] = (v, p) => m.ShakeDistance = reader.Double(v, p),
                ["shakeDegrees"] = (v, p) => m.ShakeDegrees = reader.Double(v, p),
                ["readout"] = (v, p) => m.Readout = reader.Double(v, p),
            });
            m.Enabled = enabled ?? true;
        }
    }
}
