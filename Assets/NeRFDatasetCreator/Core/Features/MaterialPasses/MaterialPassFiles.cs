using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The five material passes (contract of issue 38, Documentation~/output-format.md) and the files a view of a capture
    /// with materials on writes: each pass that is on, and <c>r_&lt;i&gt;_material_coverage.png</c> always.
    /// </summary>
    public static class MaterialPassFiles
    {
        public static readonly MaterialPass[] All =
        {
            new MaterialPass(MaterialPassNames.Albedo, DatasetFileKind.AlbedoExr, DatasetFileKind.AlbedoPng, MaterialKeys.AlbedoPath, MaterialPngEncoding.Srgb, false, f => f.MaterialAlbedo),
            new MaterialPass(MaterialPassNames.Metallic, DatasetFileKind.MetallicExr, DatasetFileKind.MetallicPng, MaterialKeys.MetallicPath, MaterialPngEncoding.Linear, true, f => f.MaterialMetallic),
            new MaterialPass(MaterialPassNames.Roughness, DatasetFileKind.RoughnessExr, DatasetFileKind.RoughnessPng, MaterialKeys.RoughnessPath, MaterialPngEncoding.Linear, true, f => f.MaterialRoughness),
            new MaterialPass(MaterialPassNames.Specular, DatasetFileKind.SpecularExr, DatasetFileKind.SpecularPng, MaterialKeys.SpecularPath, MaterialPngEncoding.Srgb, false, f => f.MaterialSpecular),
            new MaterialPass(MaterialPassNames.Emission, DatasetFileKind.EmissionExr, null, MaterialKeys.EmissionPath, MaterialPngEncoding.None, false, f => f.MaterialEmission),
        };

        /// <summary>The pass named <paramref name="name"/>, or null.</summary>
        public static MaterialPass Named(string name)
        {
            foreach (var pass in All)
                if (pass.Name == name) return pass;
            return null;
        }

        /// <summary>Adds the files of the passes that are on (EXR, then PNG) and the coverage PNG; nothing when materials are off.</summary>
        public static void AddKinds(MaterialPassSettings settings, List<DatasetFileKind> kinds)
        {
            if (settings == null || !settings.Enabled) return;
            foreach (var pass in All)
            {
                if (!MaterialPassNames.IsOn(settings, pass.Name)) continue;
                kinds.Add(pass.Exr);
                if (pass.Png is DatasetFileKind png) kinds.Add(png);
            }
            kinds.Add(DatasetFileKind.MaterialCoveragePng);
        }

        /// <summary>Whether <paramref name="view"/> writes the material passes (the coverage PNG is written whenever any pass is).</summary>
        public static bool Writes(PlannedView view) => view.Writes(DatasetFileKind.MaterialCoveragePng);
    }
}
