using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Which render pipeline draws the material passes (issue 38; Documentation~/maintainers/inverse-rendering-capture.md).</summary>
    public enum MaterialPipeline
    {
        /// <summary>Built-in: a replacement pass reads the Standard shaders' own properties.</summary>
        BuiltIn,
        /// <summary>URP: the Rendering Debugger's material modes render the shader's own SurfaceData.</summary>
        Urp,
    }

    /// <summary>
    /// Decides, from a material's shader name and keywords alone, whether the material passes read its parameters
    /// exactly; every other material is listed by shader name and its samples get 0 in the coverage mask, never a guess.
    /// Built-in: Standard and Standard (Specular setup) without detail or parallax maps, the replacement pass of
    /// <c>Shaders/NerfMaterial.shader</c> reproducing <c>UnityStandardInput.cginc</c>'s <c>Albedo</c>, <c>MetallicGloss</c>,
    /// <c>SpecularGloss</c> and <c>Emission</c>. URP: Lit and Complex Lit, whose forward pass returns the Rendering
    /// Debugger's colour (URP 14.0.8 <c>ShaderLibrary/Lighting.hlsl:262</c> → <c>Debug/Debugging3D.hlsl:116-163</c>).
    /// </summary>
    public static class MaterialShaderSupport
    {
        public const string Standard = "Standard";
        public const string StandardSpecular = "Standard (Specular setup)";

        /// <summary>Standard's detail albedo (<c>UnityStandardInput.cginc</c> <c>Albedo()</c>, the <c>_DETAIL</c> branch) and parallax UV shift (<c>Parallax()</c>): not reproduced.</summary>
        public static readonly IReadOnlyList<string> InexactStandardKeywords = new[] { "_DETAIL_MULX2", "_PARALLAXMAP" };

        /// <summary>URP's specular workflow (<c>LitInput.hlsl</c> <c>InitializeStandardLitSurfaceData</c>: metallic is set to 1, specular holds the colour).</summary>
        public const string UrpSpecularSetupKeyword = "_SPECULAR_SETUP";

        static readonly HashSet<string> UrpShaders = new HashSet<string>(StringComparer.Ordinal)
        {
            "Universal Render Pipeline/Lit",
            "Universal Render Pipeline/Complex Lit",
        };

        /// <summary>Null when the passes read this material exactly; else why not, for the capture summary.</summary>
        public static string WhyUnsupported(MaterialPipeline pipeline, MaterialSnapshot material)
        {
            if (material == null) return "an empty material slot";
            var name = material.ShaderName;
            if (pipeline == MaterialPipeline.Urp)
                return UrpShaders.Contains(name) ? null
                    : "shader '" + name + "' is not URP Lit or Complex Lit (its Rendering Debugger output is not verified)";
            if (name != Standard && name != StandardSpecular)
                return "shader '" + name + "' is not Standard or Standard (Specular setup)";
            foreach (var keyword in InexactStandardKeywords)
                if (material.Keywords.Contains(keyword))
                    return "shader '" + name + "' with " + (keyword == "_PARALLAXMAP" ? "a height (parallax) map" : "detail maps") +
                           ", which the material passes do not reproduce";
            return null;
        }

        /// <summary>
        /// True where the material is in a specular workflow: it has no metallic value (its metallic pass is written 0)
        /// and its specular colour is the specular pass. False in the metallic workflow (specular pass 0).
        /// </summary>
        public static bool IsSpecularSetup(MaterialPipeline pipeline, MaterialSnapshot material) =>
            material != null && (pipeline == MaterialPipeline.Urp
                ? material.Keywords.Contains(UrpSpecularSetupKeyword)
                : material.ShaderName == StandardSpecular);

        /// <summary>Perceptual roughness from the shader's smoothness: 1 − smoothness, clamped to [0, 1].</summary>
        public static float RoughnessFromSmoothness(float smoothness)
        {
            var r = 1f - smoothness;
            return r < 0 ? 0 : r > 1 ? 1 : r;
        }

        /// <summary>The keywords the Editor layer records for these rules.</summary>
        public static readonly IReadOnlyList<string> Keywords = new[] { "_DETAIL_MULX2", "_PARALLAXMAP", UrpSpecularSetupKeyword, "_METALLICGLOSSMAP", "_SPECGLOSSMAP", "_EMISSION", DataPassRules.SmoothnessInAlbedoAlphaKeyword };
    }
}
