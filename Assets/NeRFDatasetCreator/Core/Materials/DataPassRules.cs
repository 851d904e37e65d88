using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Decides, from a material's shader name and properties alone, how the data passes must draw it to cover what
    /// its colour pass covers (cull mode, alpha clipping). Known: Unity's Built-in Standard, Unlit and Legacy shaders,
    /// URP's Lit / Complex Lit / Simple Lit / Unlit / Baked Lit, and Shader Graph shaders through the material
    /// properties Shader Graph generates. Anything else is drawn opaque, front faces only, with a warning.
    /// The source lines each rule rests on are in Documentation~/capture.md, "Materials in the data passes".
    /// </summary>
    public static class DataPassRules
    {
        // URP: Lit.shader:50 `_Cull("__cull", Float) = 2.0`, used as `Cull[_Cull]` in every pass (:106, :315 DepthOnly).
        // Shader Graph's URP target writes the same name (Editor/ShaderGraph/UniversalProperties.cs:23).
        public const string UrpCull = "_Cull";
        // Shader Graph's Built-in target, with "Allow Material Override".
        public const string BuiltInGraphCull = "_BUILTIN_CullMode";
        // URP: Lit.shader:51 `_AlphaClip`; BaseShaderGUI.cs:903-906 turns it into the _ALPHATEST_ON keyword.
        public const string UrpAlphaClip = "_AlphaClip";
        public const string BuiltInGraphAlphaClip = "_BUILTIN_AlphaClip";
        public const string Cutoff = "_Cutoff";
        public const string MainTex = "_MainTex";
        public const string BaseMap = "_BaseMap";
        public const string Color = "_Color";
        public const string BaseColor = "_BaseColor";
        // Both pipelines compile clipping in with this keyword: Standard.shader:76, URP ShaderVariablesFunctions.hlsl:214-219.
        public const string AlphaTestKeyword = "_ALPHATEST_ON";
        public const string BuiltInGraphAlphaTestKeyword = "_BUILTIN_ALPHATEST_ON";
        // With these, the albedo alpha holds smoothness and alpha is the colour's alone (UnityStandardInput.cginc:110-117,
        // URP SurfaceInput.hlsl:21-27).
        public const string SmoothnessInAlbedoAlphaKeyword = "_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A";
        public const string GlossinessInBaseAlphaKeyword = "_GLOSSINESS_FROM_BASE_ALPHA";

        /// <summary>The float properties the Editor layer reads into a <see cref="MaterialSnapshot"/> (when the material has them).</summary>
        public static readonly IReadOnlyList<string> FloatProperties = new[] { UrpCull, BuiltInGraphCull, UrpAlphaClip, BuiltInGraphAlphaClip, Cutoff };

        /// <summary>The colour properties whose alpha the Editor layer reads.</summary>
        public static readonly IReadOnlyList<string> ColorProperties = new[] { Color, BaseColor };

        /// <summary>The texture properties the Editor layer records as present.</summary>
        public static readonly IReadOnlyList<string> TextureProperties = new[] { MainTex, BaseMap };

        /// <summary>The keywords the Editor layer records as enabled.</summary>
        public static readonly IReadOnlyList<string> Keywords = new[]
        {
            AlphaTestKeyword, BuiltInGraphAlphaTestKeyword, SmoothnessInAlbedoAlphaKeyword, GlossinessInBaseAlphaKeyword,
        };

        const string LegacyCutoutPrefix = "Legacy Shaders/Transparent/Cutout/";
        const string LegacyParticlesPrefix = "Legacy Shaders/Particles/";
        const string LegacyPrefix = "Legacy Shaders/";

        static readonly HashSet<string> UrpShaders = new HashSet<string>(StringComparer.Ordinal)
        {
            "Universal Render Pipeline/Lit",
            "Universal Render Pipeline/Complex Lit",
            "Universal Render Pipeline/Simple Lit",
            "Universal Render Pipeline/Unlit",
            "Universal Render Pipeline/Baked Lit",
        };

        // Built-in shaders that are opaque to the data passes: no Cull statement (so Cull Back) and no clip.
        // "Unlit/Transparent" blends but neither clips nor culls differently: its coverage is its geometry.
        static readonly HashSet<string> BuiltInOpaque = new HashSet<string>(StringComparer.Ordinal)
        {
            "Unlit/Texture", "Unlit/Color", "Unlit/Transparent",
        };

        /// <summary>How the data passes draw <paramref name="material"/>; null (an empty material slot) draws opaque.</summary>
        public static DataPassSettings For(MaterialSnapshot material)
        {
            if (material == null) return DataPassSettings.Opaque();
            var name = material.ShaderName;

            if (name == "Standard" || name == "Standard (Specular setup)")
            {
                // No Cull statement outside the META pass (Standard.shader:207), so Cull Back; clip under _ALPHATEST_ON
                // (UnityStandardCore.cginc:251-254), alpha = _MainTex.a × _Color.a (UnityStandardInput.cginc:110-117).
                var albedoAlpha = !material.Keywords.Contains(SmoothnessInAlbedoAlphaKeyword);
                return Clipped(material, FaceCulling.Back, material.Keywords.Contains(AlphaTestKeyword),
                    albedoAlpha ? MainTex : null, Color);
            }
            if (BuiltInOpaque.Contains(name)) return DataPassSettings.Opaque();
            if (name == "Unlit/Transparent Cutout")
                // Unlit-AlphaTest.shader:58-59: clip(tex2D(_MainTex, uv).a − _Cutoff); no colour.
                return Clipped(material, FaceCulling.Back, true, MainTex, null);
            if (name.StartsWith(LegacyCutoutPrefix, StringComparison.Ordinal))
            {
                // Surface shaders with `alphatest:_Cutoff` and o.Alpha = tex.a × _Color.a (AlphaTest-Diffuse.shader:15,25);
                // Soft Edge Unlit draws both faces (AlphaTest-SoftEdgeUnlit.shader:26, :72-73).
                var cull = name == LegacyCutoutPrefix + "Soft Edge Unlit" ? FaceCulling.Off : FaceCulling.Back;
                return Clipped(material, cull, true, MainTex, Color);
            }
            if (name.StartsWith(LegacyPrefix, StringComparison.Ordinal) && !name.StartsWith(LegacyParticlesPrefix, StringComparison.Ordinal))
                return DataPassSettings.Opaque(); // none of them has a Cull statement or clips
            if (UrpShaders.Contains(name))
            {
                // Cull[_Cull] in every pass; AlphaDiscard clips alpha = _BaseMap.a × _BaseColor.a below _Cutoff under
                // _ALPHATEST_ON (DepthOnlyPass.hlsl:39, SurfaceInput.hlsl:21-32, UnlitForwardPass.hlsl:109-111).
                var albedoAlpha = !material.Keywords.Contains(SmoothnessInAlbedoAlphaKeyword) &&
                                  !material.Keywords.Contains(GlossinessInBaseAlphaKeyword);
                return Clipped(material, CullFrom(material, UrpCull), material.Keywords.Contains(AlphaTestKeyword),
                    albedoAlpha ? BaseMap : null, BaseColor);
            }
            if (material.IsShaderGraph) return ForShaderGraph(material);
            return DataPassSettings.Opaque("the shader '" + name + "' is not one whose cull mode and alpha clipping the capture " +
                "knows, so its mask, depth and normals are drawn opaque, front faces only");
        }

        /// <summary>
        /// A graph's alpha is computed by the graph, so clipping cannot be reproduced; its Render Face can, when the
        /// material carries it ("Allow Material Override").
        /// </summary>
        static DataPassSettings ForShaderGraph(MaterialSnapshot material)
        {
            var cullProperty = material.Floats.ContainsKey(UrpCull) ? UrpCull
                : material.Floats.ContainsKey(BuiltInGraphCull) ? BuiltInGraphCull : null;
            var clips = material.Keywords.Contains(AlphaTestKeyword) || material.Keywords.Contains(BuiltInGraphAlphaTestKeyword) ||
                        FloatIsOn(material, UrpAlphaClip) || FloatIsOn(material, BuiltInGraphAlphaClip);
            string warning = null;
            if (cullProperty == null)
                warning = "the Shader Graph '" + material.ShaderName + "' keeps its Render Face and Alpha Clipping inside the " +
                          "shader (enable Allow Material Override in its Graph Settings to expose them), so its mask, depth " +
                          "and normals are drawn opaque, front faces only";
            else if (clips)
                warning = "the Shader Graph '" + material.ShaderName + "' clips by an alpha the graph computes, which the capture " +
                          "cannot reproduce, so its mask, depth and normals are drawn without its alpha clipping";
            return new DataPassSettings(cullProperty == null ? FaceCulling.Back : CullFrom(material, cullProperty), false, 0, null, 1, warning);
        }

        static DataPassSettings Clipped(MaterialSnapshot material, FaceCulling cull, bool clip, string texture, string color)
        {
            if (!clip) return new DataPassSettings(cull, false, 0, null, 1, null);
            var cutoff = material.Floats.TryGetValue(Cutoff, out var c) ? c : 0.5; // 0.5: every listed shader's default
            var textureProperty = texture != null && material.Textures.Contains(texture) ? texture : null;
            var colorAlpha = color != null && material.ColorAlphas.TryGetValue(color, out var a) ? a : 1.0;
            return new DataPassSettings(cull, true, cutoff, textureProperty, colorAlpha, null);
        }

        /// <summary>The cull mode stored in a float property; anything but 0, 1 or 2 (or none) is Unity's default, Back.</summary>
        static FaceCulling CullFrom(MaterialSnapshot material, string property)
        {
            if (!material.Floats.TryGetValue(property, out var value)) return FaceCulling.Back;
            var rounded = Math.Round(value);
            if (rounded == 0) return FaceCulling.Off;
            if (rounded == 1) return FaceCulling.Front;
            return FaceCulling.Back;
        }

        static bool FloatIsOn(MaterialSnapshot material, string property) =>
            material.Floats.TryGetValue(property, out var value) && value >= 0.5; // BaseShaderGUI.cs:904: >= 0.5
    }
}
