namespace NerfDatasetCreator
{
    /// <summary>
    /// Relightable 3D Gaussians' Synthetic4Relight layout (NJU-3DV/Relightable3DGaussian at a102f14): the reader is picked
    /// by the word <c>Synthetic4Relight</c> in the source path (scene/__init__.py:51); train views are
    /// <c>file_path + "_rgb.exr"</c> (linear, sRGB-encoded on load: scene/utils.py:42–45) with
    /// <c>_mask.png</c> beside (dataset_readers.py:536, 552; any non-zero code is inside, utils.py:52–57), test views
    /// <c>file_path + "_rgba.png"</c> (:573) masked by the same file read as grey — non-black RGB (:536 leaves the path
    /// unchanged, :552); the focal is fov2focal(fovx, H) and the other axis focal2fov(…, W) (:557), right only for square
    /// images. Its evaluation (eval_relighting_syn4.py) reads <c>test_rli/&lt;env&gt;_&lt;name&gt;.png</c> (:129, alpha as mask,
    /// :140–142), <c>test/&lt;name&gt;_albedo.png</c> (:174) and <c>test/&lt;name&gt;_rough.png</c> (:180), lit by
    /// <c>env_map/&lt;env&gt;.exr</c> (:64, :68).
    /// </summary>
    public static class R3dg
    {
        /// <summary>The default folder: its name carries the word the reader is picked by.</summary>
        public const string FolderName = "Synthetic4Relight";

        public const string PathWord = "Synthetic4Relight";
        public const string RelitFolder = "test_rli", EnvironmentFolder = "env_map";

        public static string TrainImage(string stem) => stem + "_rgb.exr";
        public static string TrainMask(string stem) => stem + "_mask.png";
        public static string TestImage(string stem) => stem + "_rgba.png";
        public static string Albedo(string stem) => stem + "_albedo.png";
        public static string Roughness(string stem) => stem + "_rough.png";
        public static string Relit(string key, string stem) => key + "_" + stem + ".png";
    }
}
