namespace NerfDatasetCreator
{
    /// <summary>
    /// What the window's Material passes section (step 5, Outputs; issue 38) shows: the settings key its problems are
    /// reported under and the note on what the active render pipeline reads.
    /// </summary>
    public static class MaterialPassChoices
    {
        /// <summary>The settings section ("materials"); the section shows every "materials.…" problem.</summary>
        public const string Field = "materials";

        /// <summary>The pass toggles' labels, in MaterialPassSettings order (albedo, metallic, roughness, specular, emission).</summary>
        public static readonly string[] PassLabels = { "Base colour (albedo)", "Metallic", "Roughness (1 − smoothness)", "Specular colour", "Emission" };

        /// <summary>Per view, the files the enabled passes write (the EXR beside each PNG; emission is EXR only).</summary>
        public static int FilesPerView(MaterialPassSettings m)
        {
            if (m == null || !m.Enabled) return 0;
            var files = 1; // r_<i>_material_coverage.png
            foreach (var on in new[] { m.Albedo, m.Metallic, m.Roughness, m.Specular })
                if (on) files += 2;
            if (m.Emission) files += 1;
            return files;
        }

        /// <summary>What the passes read in this pipeline ("Built-in" or a pipeline asset's type name, as the capture names it).</summary>
        public static string PipelineNote(string renderPipelineName) =>
            renderPipelineName == "UniversalRenderPipelineAsset"
                ? "URP: the Rendering Debugger's material modes read URP Lit and Complex Lit exactly; other shaders are listed in the summary and left out (0 in the coverage mask)."
                : renderPipelineName == "Built-in"
                    ? "Built-in: Standard and Standard (Specular setup) are read exactly (without detail or height maps); other shaders are listed in the summary and left out (0 in the coverage mask)."
                    : "Material passes need the Built-in pipeline or URP 14 or later.";
    }
}
