namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-frame keys of the material passes (issue 38, Documentation~/output-format.md): each names the pass's 8-bit
    /// PNG; its float EXR truth is the same path with <c>.exr</c>. Emission has only the EXR. No loader reads these keys
    /// from a transforms file, so the names are ours, in the snake_case of the other file keys.
    /// </summary>
    public static class MaterialKeys
    {
        public const string AlbedoPath = "albedo_path";
        public const string MetallicPath = "metallic_path";
        public const string RoughnessPath = "roughness_path";
        public const string SpecularPath = "specular_path";
        public const string EmissionPath = "emission_path";
        public const string CoveragePath = "material_coverage_path";

        /// <summary>The keys of the passes <paramref name="v"/> writes, in <see cref="MaterialPassFiles.All"/>'s order, then the coverage's.</summary>
        internal static void WriteFrameFiles(TransformsFramesText frame, PlannedView v)
        {
            foreach (var pass in MaterialPassFiles.All) frame.FileKey(v, pass.KeyFile, pass.Key);
            frame.FileKey(v, DatasetFileKind.MaterialCoveragePng, CoveragePath);
        }

        /// <summary>The material files <paramref name="frame"/> names (<see cref="FrameMaterials"/>), resolved from its keys only.</summary>
        public static FrameMaterials Read(DatasetFrame frame) => FrameMaterials.Of(frame);
    }
}
