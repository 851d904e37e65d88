using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>dataset_config.json</c>'s <c>unity_frame</c> (issue 34): the 4×4 that takes the output frame back into Unity's
    /// world, x_unity = M·[x_out, 1], with x_out = s·(B·x_unity − c) and B(x, y, z) = (x, z, y), so M = [B/s | B·c]
    /// (determinant −1/s³: the map reflects), and what only the Editor knows (<see cref="UnityFrameFacts"/>). A dataset
    /// written before the key existed gets the same matrix from its <c>scene_normalisation</c> (<see cref="Derived"/>).
    /// </summary>
    public sealed class UnityFrameRecord
    {
        public const string Key = "unity_frame";

        UnityFrameRecord(Matrix4x4d outputToUnity, UnityFrameFacts facts, string derivedFrom)
        {
            OutputToUnity = outputToUnity;
            Facts = facts;
            DerivedFrom = derivedFrom;
        }

        /// <summary>x_unity = OutputToUnity·[x_out, 1].</summary>
        public Matrix4x4d OutputToUnity { get; }

        /// <summary>The Editor's facts (scene path, GlobalObjectId, local-to-world, colour space); members null when not recorded.</summary>
        public UnityFrameFacts Facts { get; }

        /// <summary>Null when read from <c>unity_frame</c>; otherwise where the matrix came from (e.g. "dataset_config.json's scene_normalisation").</summary>
        public string DerivedFrom { get; }

        public bool Derived => DerivedFrom != null;

        /// <summary>M = [B/s | B·c] for the similarity x_out = s·(B·x_unity − c).</summary>
        public static Matrix4x4d Matrix(SceneNormalisation normalisation)
        {
            var inverse = 1 / normalisation.Scale;
            return Matrix4x4d.FromColumns(new Vector3d(inverse, 0, 0), new Vector3d(0, 0, inverse), new Vector3d(0, inverse, 0),
                BlenderConvention.ToUnity(normalisation.Centre));
        }

        /// <summary>The record <see cref="DatasetConfig.Write"/> writes: the matrix parts always, the Editor's facts when known (null otherwise).</summary>
        public static JObject ToJson(SceneNormalisation normalisation, UnityFrameFacts facts)
        {
            var m = Matrix(normalisation);
            var det = m.Determinant3x3;
            return new JObject
            {
                ["output_to_unity"] = ExportJson.Matrix(m),
                ["meaning"] = "x_unity = output_to_unity · [x_out, 1] (row-major 4×4, Unity world); the inverse of scene_normalisation with the (x, z, y) axis swap",
                ["determinant"] = det,
                ["determinant_sign"] = det < 0 ? "negative: the map reflects (Blender's right-handed axes into Unity's left-handed ones); a Transform carries it as one negative scale component" : "positive",
                ["target_scene_path"] = facts?.TargetScenePath,
                ["target_global_object_id"] = facts?.TargetGlobalObjectId,
                ["target_local_to_world"] = facts?.TargetLocalToWorld == null ? null : ExportJson.Matrix(Matrix4x4d.FromRowMajor(facts.TargetLocalToWorld)),
                ["color_space"] = facts?.ColorSpace,
            };
        }

        /// <summary>
        /// The frame recorded in <paramref name="json"/> (dataset_config.json, or a transforms file that carries the same
        /// top-level keys): <c>unity_frame</c>, else derived from <c>scene_normalisation</c>; null when neither is there.
        /// A malformed record is refused naming <paramref name="fileName"/> and the field.
        /// </summary>
        public static UnityFrameRecord Read(JObject json, string fileName = DatasetLayout.ConfigFileName)
        {
            var token = json?[Key];
            if (token != null && token.Type != JTokenType.Null) return Parse(token, fileName);
            if (json?[BlenderTransformsWriter.SceneNormalisationKey] is JObject normalisation)
                return new UnityFrameRecord(Matrix(SceneNormalisation.FromJson(normalisation)), null, fileName + "'s " + BlenderTransformsWriter.SceneNormalisationKey);
            return null;
        }

        static UnityFrameRecord Parse(JToken token, string fileName)
        {
            var o = token as JObject;
            var matrix = Matrix4(o?["output_to_unity"]);
            if (o == null || matrix == null || !matrix.Value.IsFinite || matrix.Value.Determinant3x3 == 0)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(fileName + ": " + Key + ".output_to_unity", Shown(o?["output_to_unity"] ?? token),
                        "is not an invertible 4×4 matrix of numbers (4 rows of 4).", "Remove the unity_frame key (scene_normalisation then gives the same matrix), or capture again."),
                });
            var localToWorld = Matrix4(o["target_local_to_world"]);
            var facts = new UnityFrameFacts(Text(o["target_scene_path"]), Text(o["target_global_object_id"]),
                localToWorld == null ? null : Enumerable.Range(0, 16).Select(i => localToWorld.Value[i / 4, i % 4]).ToArray(), Text(o["color_space"]));
            return new UnityFrameRecord(matrix.Value, facts, null);
        }

        static string Shown(JToken token)
        {
            var text = token?.ToString(Newtonsoft.Json.Formatting.None) ?? "missing";
            return text.Length > 120 ? text.Substring(0, 117) + "..." : text;
        }

        static string Text(JToken token) => token?.Type == JTokenType.String ? (string)token : null;

        /// <summary>A 4×4 written as 4 rows of 4 numbers, or null.</summary>
        static Matrix4x4d? Matrix4(JToken token)
        {
            if (!(token is JArray rows) || rows.Count != 4) return null;
            var values = new List<double>(16);
            foreach (var row in rows)
            {
                if (!(row is JArray r) || r.Count != 4) return null;
                foreach (var v in r)
                {
                    if (!JsonValues.TryNumber(v, out var d)) return null;
                    values.Add(d);
                }
            }
            return Matrix4x4d.FromRowMajor(values.ToArray());
        }
    }
}
