using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <c>dataset_config.json</c> says about the geometry pack, under <see cref="Key"/>:
    /// <c>{"file": "geometry/target_mesh.ply", "frame": …, "sha256": …, "vertices": n, "triangles": n,
    /// "objects": [{"name", "vertices", "triangles"}…]}</c> — the objects in the order of the PLY's faces.
    /// </summary>
    public static class GeometryPackRecord
    {
        public const string Key = "geometry";

        public const string FrameText =
            "output world (Blender axes, right-handed, +Z up) after scene_normalisation, the frame of transform_matrix; units = output units (depth PNG value / 1000); faces counter-clockwise seen from outside";

        public static JObject ToJson(IReadOnlyList<SurfaceMesh> outputMeshes, string sha256) => new JObject
        {
            ["file"] = TargetMeshPly.RelativePath,
            ["frame"] = FrameText,
            ["sha256"] = sha256,
            ["vertices"] = outputMeshes.Sum(m => (long)m.Vertices.Count),
            ["triangles"] = outputMeshes.Sum(m => (long)m.TriangleCount),
            ["objects"] = new JArray(outputMeshes.Select(m => new JObject
            {
                ["name"] = m.Name,
                ["vertices"] = m.Vertices.Count,
                ["triangles"] = m.TriangleCount,
            })),
        };

        /// <summary>
        /// The recorded single file (relative to the dataset), or null when the config records no geometry pack or a
        /// per-step one (<see cref="GeometryPackStepRecord"/>).
        /// </summary>
        public static string RecordedFile(JObject config) =>
            config?[Key] is JObject geometry && geometry["file"]?.Type == JTokenType.String ? (string)geometry["file"] : null;

        /// <summary>
        /// The single mesh of a dynamic capture, at its start time: the same record plus that step's <c>step</c> (0),
        /// <c>time</c> (0, the D-NeRF <c>time</c> key of the views it matches) and <c>time_seconds</c>.
        /// </summary>
        public static JObject ToJson(IReadOnlyList<SurfaceMesh> outputMeshes, string sha256, ViewTime time)
        {
            var json = ToJson(outputMeshes, sha256);
            GeometryPackStepRecord.AddTime(json, time);
            return json;
        }
    }
}
