using System;
using System.Collections.Generic;
using UnityEngine;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The materials the material passes draw with: one of <see cref="ShaderName"/> per source material, made on first
    /// use and kept for the run. Each carries the data passes' cull mode and alpha clip (Core <see cref="DataPassRules"/>),
    /// whether Core's <see cref="MaterialShaderSupport"/> reads the source exactly, and, for a supported Built-in
    /// Standard material, the source's own property values under the same names and declarations (NerfMaterial.shader's
    /// header). Records the supported and unsupported shaders seen, for the capture summary. Owns and destroys them all.
    /// </summary>
    sealed class MaterialPassMaterials : IDisposable
    {
        public const string ShaderName = "Hidden/NerfDatasetCreator/Material";

        readonly Shader _shader;
        readonly MaterialPipeline _pipeline;
        readonly Dictionary<Material, Material> _bySource = new Dictionary<Material, Material>();
        readonly SortedSet<string> _supported = new SortedSet<string>(StringComparer.Ordinal);
        readonly SortedDictionary<string, string> _unsupported = new SortedDictionary<string, string>(StringComparer.Ordinal);
        Material _forEmptySlot;

        public MaterialPassMaterials(MaterialPipeline pipeline)
        {
            _pipeline = pipeline;
            _shader = PackageShader.Find(ShaderName);
        }

        /// <summary>Shader names whose parameters the passes read exactly.</summary>
        public IReadOnlyCollection<string> SupportedShaders => _supported;

        /// <summary>Every other shader seen, by name, with the reason (its samples are 0 in the coverage mask).</summary>
        public IReadOnlyDictionary<string, string> UnsupportedShaders => _unsupported;

        public Material For(Material source)
        {
            if (source == null)
            {
                if (_forEmptySlot == null)
                {
                    _forEmptySlot = Create(DataPassSettings.Opaque(), "an empty slot");
                    _unsupported["(empty material slot)"] = MaterialShaderSupport.WhyUnsupported(_pipeline, null);
                }
                return _forEmptySlot;
            }
            if (_bySource.TryGetValue(source, out var made)) return made;
            var snapshot = Snapshot(source);
            var why = MaterialShaderSupport.WhyUnsupported(_pipeline, snapshot);
            if (why == null) _supported.Add(snapshot.ShaderName);
            else _unsupported[snapshot.ShaderName + (snapshot.Keywords.Overlaps(MaterialShaderSupport.InexactStandardKeywords) ? " (" + source.name + ")" : "")] = why;
            var settings = DataPassRules.For(DataPassMaterials.Snapshot(source));
            var material = Create(settings, source.name);
            material.SetFloat("_NerfSupported", why == null ? 1f : 0f);
            material.SetFloat("_NerfSpecularSetup", why == null && MaterialShaderSupport.IsSpecularSetup(_pipeline, snapshot) ? 1f : 0f);
            if (why == null && _pipeline == MaterialPipeline.BuiltIn) CopyStandardProperties(source, snapshot, material);
            if (settings.AlphaTexture != null)
            {
                // The data passes' clip (DataPassMaterials.Create): the same texture, scale and offset.
                material.SetTexture("_NerfAlphaTex", source.GetTexture(settings.AlphaTexture));
                material.SetTextureScale("_NerfAlphaTex", source.GetTextureScale(settings.AlphaTexture));
                material.SetTextureOffset("_NerfAlphaTex", source.GetTextureOffset(settings.AlphaTexture));
            }
            _bySource.Add(source, material);
            return material;
        }

        /// <summary>The shader name and the keywords <see cref="MaterialShaderSupport"/> reads.</summary>
        internal static MaterialSnapshot Snapshot(Material material)
        {
            var snapshot = new MaterialSnapshot(material.shader.name);
            foreach (var keyword in MaterialShaderSupport.Keywords)
                if (material.IsKeywordEnabled(keyword)) snapshot.WithKeyword(keyword);
            return snapshot;
        }

        /// <summary>
        /// Standard's values under the same property names (Standard.shader:7-32, StandardSpecular.shader:15-16); the
        /// keywords that select its branches (Standard.shader:75-83 shader_feature lines) become 0/1 floats.
        /// Material.GetColor/GetFloat return the values as set in the inspector; Unity applies the colour-space
        /// conversion (Color properties, [Gamma] _Metallic) when it uploads them, to NerfMaterial.shader's identically
        /// declared properties exactly as to Standard's.
        /// </summary>
        static void CopyStandardProperties(Material source, MaterialSnapshot snapshot, Material target)
        {
            CopyColor(source, "_Color", target, "_Color");
            CopyTexture(source, "_MainTex", target, withScaleOffset: true);
            CopyFloat(source, "_Glossiness", target);
            CopyFloat(source, "_GlossMapScale", target);
            CopyFloat(source, "_Metallic", target);
            CopyTexture(source, "_MetallicGlossMap", target, withScaleOffset: false);
            CopyColor(source, "_SpecColor", target, "_NerfSpecColor");
            CopyTexture(source, "_SpecGlossMap", target, withScaleOffset: false);
            CopyColor(source, "_EmissionColor", target, "_EmissionColor");
            CopyTexture(source, "_EmissionMap", target, withScaleOffset: false);
            target.SetFloat("_NerfMetallicMap", snapshot.Keywords.Contains("_METALLICGLOSSMAP") ? 1f : 0f);
            target.SetFloat("_NerfSpecMap", snapshot.Keywords.Contains("_SPECGLOSSMAP") ? 1f : 0f);
            target.SetFloat("_NerfSmoothnessFromAlbedo", snapshot.Keywords.Contains(DataPassRules.SmoothnessInAlbedoAlphaKeyword) ? 1f : 0f);
            target.SetFloat("_NerfEmission", snapshot.Keywords.Contains("_EMISSION") ? 1f : 0f);
        }

        static void CopyColor(Material source, string name, Material target, string targetName)
        {
            if (source.HasProperty(name)) target.SetColor(targetName, source.GetColor(name));
        }

        static void CopyFloat(Material source, string name, Material target)
        {
            if (source.HasProperty(name)) target.SetFloat(name, source.GetFloat(name));
        }

        static void CopyTexture(Material source, string name, Material target, bool withScaleOffset)
        {
            if (!source.HasProperty(name)) return;
            // An empty slot stays null and samples the declared default ("white"), as Standard's does.
            target.SetTexture(name, source.GetTexture(name));
            if (!withScaleOffset) return;
            target.SetTextureScale(name, source.GetTextureScale(name));
            target.SetTextureOffset(name, source.GetTextureOffset(name));
        }

        Material Create(DataPassSettings settings, string sourceName)
        {
            var material = new Material(_shader) { name = "NeRF material pass for " + sourceName, hideFlags = HideFlags.HideAndDontSave };
            material.SetFloat("_NerfCull", (float)settings.Cull);
            material.SetFloat("_NerfClip", settings.AlphaClip ? 1f : 0f);
            material.SetFloat("_NerfCutoff", (float)settings.Cutoff);
            material.SetFloat("_NerfColorAlpha", (float)settings.ColorAlpha);
            return material;
        }

        public void Dispose()
        {
            foreach (var material in _bySource.Values)
                if (material != null) Object.DestroyImmediate(material);
            _bySource.Clear();
            if (_forEmptySlot != null) Object.DestroyImmediate(_forEmptySlot);
            _forEmptySlot = null;
        }
    }
}
