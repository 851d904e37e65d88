using System;
using System.Collections.Generic;
using UnityEngine;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The materials the data passes draw with: one of <see cref="ShaderName"/> per source material, set up from
    /// Core's <see cref="DataPassRules"/> (cull mode, alpha clipping), made on first use and kept for the run. A shader
    /// the rules cannot reproduce is reported once per run with a warning naming it. Owns and destroys them all.
    /// </summary>
    sealed class DataPassMaterials : IDisposable
    {
        public const string ShaderName = "Hidden/NerfDatasetCreator/Data";

        static readonly int CullId = Shader.PropertyToID("_NerfCull");
        static readonly int ClipId = Shader.PropertyToID("_NerfClip");
        static readonly int CutoffId = Shader.PropertyToID("_NerfCutoff");
        static readonly int ColorAlphaId = Shader.PropertyToID("_NerfColorAlpha");
        const string AlphaTexture = "_NerfAlphaTex";

        // Shader Graph writes this SubShader tag into every shader it generates; URP's own converter tells graphs apart
        // by it (URP 14.0.8 Editor/UniversalRenderPipelineMaterialUpgrader.cs:229-230).
        const string ShaderGraphTag = "ShaderGraphShader";

        readonly Shader _shader;
        readonly Dictionary<Material, Material> _bySource = new Dictionary<Material, Material>();
        readonly HashSet<string> _warnedShaders = new HashSet<string>(StringComparer.Ordinal);
        Material _forEmptySlot;

        public DataPassMaterials()
        {
            _shader = PackageShader.Find(ShaderName);
        }

        /// <summary>Shaders seen so far that the data passes draw only approximately (each was warned about once).</summary>
        public IReadOnlyCollection<string> ApproximatedShaders => _warnedShaders;

        /// <summary>The data material standing in for <paramref name="source"/> (null: an empty slot, drawn opaque).</summary>
        public Material For(Material source)
        {
            if (source == null)
            {
                if (_forEmptySlot == null) _forEmptySlot = Create(DataPassSettings.Opaque(), null, "an empty slot");
                return _forEmptySlot;
            }
            if (_bySource.TryGetValue(source, out var data)) return data;
            var settings = DataPassRules.For(Snapshot(source));
            if (settings.Warning != null && _warnedShaders.Add(source.shader.name))
                Debug.LogWarning("NeRF Dataset Creator: " + settings.Warning + " (first seen on the material '" + source.name +
                                 "'). The colour images are not affected.");
            data = Create(settings, source, source.name);
            _bySource.Add(source, data);
            return data;
        }

        /// <summary>The properties and keywords <see cref="DataPassRules"/> reads, as the material has them.</summary>
        internal static MaterialSnapshot Snapshot(Material material)
        {
            var snapshot = new MaterialSnapshot(material.shader.name, material.GetTag(ShaderGraphTag, false, "") != "");
            foreach (var name in DataPassRules.FloatProperties)
                if (material.HasProperty(name)) snapshot.WithFloat(name, material.GetFloat(name));
            foreach (var name in DataPassRules.ColorProperties)
                if (material.HasProperty(name)) snapshot.WithColorAlpha(name, material.GetColor(name).a);
            foreach (var name in DataPassRules.TextureProperties)
                if (material.HasProperty(name)) snapshot.WithTexture(name);
            foreach (var keyword in DataPassRules.Keywords)
                if (material.IsKeywordEnabled(keyword)) snapshot.WithKeyword(keyword);
            return snapshot;
        }

        Material Create(DataPassSettings settings, Material source, string sourceName)
        {
            var data = new Material(_shader) { name = "NeRF data pass for " + sourceName, hideFlags = HideFlags.HideAndDontSave };
            data.SetFloat(CullId, (float)settings.Cull);
            data.SetFloat(ClipId, settings.AlphaClip ? 1f : 0f);
            data.SetFloat(CutoffId, (float)settings.Cutoff);
            data.SetFloat(ColorAlphaId, (float)settings.ColorAlpha);
            if (source != null && settings.AlphaTexture != null)
            {
                // An empty slot stays null, which samples the data shader's default "white" (alpha 1), as the source would.
                data.SetTexture(AlphaTexture, source.GetTexture(settings.AlphaTexture));
                data.SetTextureScale(AlphaTexture, source.GetTextureScale(settings.AlphaTexture));
                data.SetTextureOffset(AlphaTexture, source.GetTextureOffset(settings.AlphaTexture));
            }
            return data;
        }

        public void Dispose()
        {
            foreach (var data in _bySource.Values)
                if (data != null) Object.DestroyImmediate(data);
            _bySource.Clear();
            if (_forEmptySlot != null) Object.DestroyImmediate(_forEmptySlot);
            _forEmptySlot = null;
        }
    }
}
