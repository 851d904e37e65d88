using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The top-level motion blur keys of a transforms file: instant-ngp's <c>rolling_shutter</c> [0, 0, ρ, 1 − ρ]
    /// (<see cref="RollingShutter"/>; [0, 0, 0, 1] for a global shutter, which makes instant-ngp draw each training
    /// ray's time uniformly over the interval) and this plugin's <c>motion_blur</c> record of how the images were made.
    /// </summary>
    public static class MotionBlurRecord
    {
        /// <summary>The keys when <paramref name="settings"/> blur the views (<see cref="ShutterPlanning.IsOn"/>); none otherwise.</summary>
        public static void WriteTopLevel(JsonWriter w, DatasetSettings settings)
        {
            if (ShutterPlanning.IsOn(settings)) WriteTopLevel(w, settings.MotionBlur);
        }

        public static void WriteTopLevel(JsonWriter w, MotionBlurSettings m)
        {
            w.WritePropertyName(MotionBlurKeys.RollingShutter);
            w.WriteStartArray();
            foreach (var value in RollingShutter.InstantNgpVector(m.Readout)) JsonNumbers.Write(w, value);
            w.WriteEndArray();
            w.WritePropertyName(MotionBlurKeys.Record);
            w.WriteStartObject();
            w.WritePropertyName("camera"); w.WriteValue(MotionBlurSettings.CameraName(m.Camera));
            JsonNumbers.Number(w, "shutter", m.Shutter);
            w.WritePropertyName("sub_frames"); w.WriteValue(m.SubFrames);
            JsonNumbers.Number(w, "readout", m.Readout);
            w.WritePropertyName("meaning");
            w.WriteValue("file_path is the average in linear light of sub_frames renders at t = (k + 0.5) / sub_frames between transform_matrix_start (t = 0) and " +
                         "transform_matrix_end (t = 1), rotation slerped and position linear; the row at v = (row + 0.5) / h (top = 0) sees t in " +
                         "[readout * v, readout * v + 1 - readout]; transform_matrix, depth, normals, masks and sharp_path are at t = 0.5");
            w.WriteEndObject();
        }
    }
}
