using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to gs-ir</c>: TensoIR-Synthetic's layout (<see cref="TensoIRExport"/>) as GS-IR reads it (lzhnb/GS-IR at
    /// e5a030b): through its Blender reader, <c>transforms_train.json</c> / <c>transforms_test.json</c> with
    /// <c>file_path + ".png"</c> (scene/dataset_readers.py:224–249, 281–290; val is not read), <c>points3d.ply</c> at the root
    /// (:299), the albedo truth at <c>file_path.replace("rgba", "albedo") + ".png"</c> with its alpha as the mask
    /// (render.py:322–324), normals from <c>test_*/normal.png</c> (normal_eval.py:29–45) and relit truth from
    /// <c>test_&lt;k:03d&gt;/rgba_&lt;light&gt;.png</c> for the k-th test frame (relight_eval.py:36) — so test frame k is written
    /// to folder <c>test_&lt;k:03d&gt;</c>, in the transforms' order.
    /// </summary>
    public static class GsIr
    {
        public const string FolderName = "gs-ir";

        /// <summary>relight_eval.py:24 (the TensoIR-Synthetic test lights) and :28.</summary>
        public static readonly string[] HardCodedLights = { "bridge", "city", "fireplace", "forest", "night" };
        public const int HardCodedTestViews = 200;

        internal static IEnumerable<ValidationProblem> Warnings(IReadOnlyList<InverseRenderingView> views, IReadOnlyList<string> relitNames)
        {
            var test = views.Count(v => v.Split == "test");
            var names = relitNames.Distinct().OrderBy(n => n, System.StringComparer.Ordinal).ToList();
            if (test != HardCodedTestViews || !names.SequenceEqual(HardCodedLights))
                yield return new ValidationProblem("relight_eval.py", test + " test views, lights " + (names.Count == 0 ? "none" : string.Join(", ", names)),
                    "differ from what GS-IR's relight_eval.py hard-codes: light_name_list = [\"bridge\", \"city\", \"fireplace\", \"forest\", \"night\"] (:24) and num_test = 200 (:28).",
                    "Paste the lines of " + TensoIR.RecordFileName + " (config.gs_ir_relight_eval_py_24 and _28) into relight_eval.py; relight.py's --hdri " + TensoIR.LightsFolder + "/<light>.hdr names its renders by the file's name (relight.py:189).");
        }

        internal static List<string> Commands(string output) => new List<string>
        {
            "python train.py -m outputs/scene/ -s " + output + " --iterations 30000 --eval   (GS-IR stage 1; then baking.py and stage 2 as its README says)",
            "python normal_eval.py --gt_dir " + output + " --output_dir outputs/scene/test/ours_None   (GS-IR normals)",
        };
    }
}
