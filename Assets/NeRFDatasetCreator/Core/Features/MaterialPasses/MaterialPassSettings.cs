using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The "materials" section of the settings (issue 38): per view, the shader's own surface parameters as passes of
    /// their own — base colour (albedo), metallic, perceptual roughness (1 − smoothness), specular colour where the shader
    /// has it, and emission — each linear, as a float EXR (the truth) beside an 8-bit PNG
    /// (Documentation~/materials.md). Off by default, and then nothing about the dataset changes.
    /// </summary>
    [Serializable]
    public sealed class MaterialPassSettings
    {
        /// <summary>On when the section is given (and not <c>"enabled": false</c>).</summary>
        public bool On;

        /// <summary>The passes written (all but specular and emission by default).</summary>
        public bool Albedo = true, Metallic = true, Roughness = true, Specular, Emission;

        public bool Enabled => On;

        public MaterialPassSettings Clone() => (MaterialPassSettings)MemberwiseClone();
    }
}
