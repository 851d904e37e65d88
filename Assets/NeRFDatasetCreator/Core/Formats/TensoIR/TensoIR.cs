using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// TensoIR-Synthetic's layout, which NeRFactor's loader reads too (Documentation~/maintainers/layouts-inverse-rendering.md
    /// cites every line): one folder per view, <c>&lt;split&gt;_&lt;NNN&gt;/</c> (TensoIR keeps every entry of the dataset
    /// folder whose name starts with the split, tensoIR_rotation_setting.py:42 at Haian-Jin/TensoIR 8f7b8dd; NeRFactor
    /// globs <c>'%s_???'</c>, nerfactor/datasets/nerf.py:69 at google/nerfactor a668dca), each with
    /// <c>metadata.json</c> (<c>cam_transform_mat</c> as 16 comma-separated numbers row-major, <c>cam_angle_x</c>,
    /// <c>imw</c>, <c>imh</c>: tensoIR_rotation_setting.py:100–108, nerf.py:145–149), <c>rgba.png</c> (nerf.py:80),
    /// <c>rgba_&lt;light&gt;.png</c> / <c>rgba_&lt;light&gt;_&lt;rot&gt;.png</c> (tensoIR_general_multi_lights.py:126,
    /// tensoIR_rotation_setting.py:120), <c>albedo.png</c> (:206) and <c>normal.png</c> (:220); transforms_&lt;split&gt;.json
    /// at the root with <c>file_path</c> <c>./&lt;split&gt;_&lt;NNN&gt;/rgba</c> (NeRFactor's data_gen/nerf_synth/render.py:58–63,
    /// the files GS-IR's Blender reader takes).
    /// </summary>
    public static class TensoIR
    {
        public const string FolderName = "tensoir";

        /// <summary>Environment maps (.hdr) and NeRFactor's OLAT light .json files: a folder whose name starts with neither train nor test.</summary>
        public const string LightsFolder = "env_maps";

        /// <summary>The export's record: which albedo and encoding, the lights and the lines to paste into each trainer's config.</summary>
        public const string RecordFileName = "inverse_rendering_export.json";

        /// <summary>NeRFactor's <c>'%s_???'</c> glob sees three digits only (nerf.py:69).</summary>
        public const int MaxViewsPerSplit = 1000;

        /// <summary>TensoIR's loaders fix img_wh at 800×800 (tensoIR_rotation_setting.py:47), which its evaluation reshapes by (renderer.py:179).</summary>
        public const int EvaluationSide = 800;

        public const string Metadata = "metadata.json", Rgba = "rgba.png", Albedo = "albedo.png", Normal = "normal.png";

        public static string ViewFolder(string split, int index) => split + "_" + index.ToString("000", CultureInfo.InvariantCulture);

        /// <summary>The view under a lighting condition's key: <c>rgba_&lt;key&gt;.png</c>.</summary>
        public static string RelitFile(string key) => "rgba_" + key + ".png";
    }
}
