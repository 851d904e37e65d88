using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>JSON as the exporters write it: <see cref="JsonNumbers"/>' numbers, invariant culture, "\n" line ends.</summary>
    public static class ExportJson
    {
        public static JArray Matrix(Matrix4x4d m) => Rows(m, 4);

        /// <summary>The upper 3×4 block: nerfstudio's <c>applied_transform</c> shape.</summary>
        public static JArray Matrix3x4(Matrix4x4d m) => Rows(m, 3);

        static JArray Rows(Matrix4x4d m, int rows)
        {
            var result = new JArray();
            for (var r = 0; r < rows; r++) result.Add(new JArray(m[r, 0], m[r, 1], m[r, 2], m[r, 3]));
            return result;
        }

        /// <summary>
        /// The pinhole keys nerfstudio and instant-ngp both read, in this order: <c>fl_x</c>, <c>fl_y</c>, <c>cx</c>,
        /// <c>cy</c>, <c>w</c>, <c>h</c> (instant-ngp divides cx/cy by w/h, so they always travel together).
        /// </summary>
        public static void AddPixelIntrinsics(JObject json, CameraIntrinsics k)
        {
            json["fl_x"] = k.FlX;
            json["fl_y"] = k.FlY;
            json["cx"] = k.Cx;
            json["cy"] = k.Cy;
            json["w"] = k.Width;
            json["h"] = k.Height;
        }

        /// <summary>
        /// The file text of <paramref name="token"/>: 2-space indentation, every double through
        /// <see cref="JsonNumbers.Format"/>, so exports write numbers exactly as the Blender split files do.
        /// </summary>
        public static string Serialise(JToken token)
        {
            using (var text = JsonNumbers.CreateText())
            {
                using (var writer = JsonNumbers.CreateWriter(text))
                    JsonNumbers.WriteToken(writer, token);
                return text.ToString() + "\n"; // the writer's text, formatted by CreateText's invariant culture
            }
        }
    }
}
