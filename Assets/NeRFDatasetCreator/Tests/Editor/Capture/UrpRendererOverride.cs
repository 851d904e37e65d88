using System;
using System.Collections;
using System.Reflection;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Changes the active URP asset and its default Universal Renderer for one test and puts everything back on
    /// Dispose. The package has no URP reference, so members are reached by the names URP 14.0.8 gives them:
    /// <c>UniversalRenderPipelineAsset.msaaSampleCount</c> (Runtime/Data/UniversalRenderPipelineAsset.cs:1072),
    /// its serialized <c>m_RendererDataList</c> / <c>m_DefaultRendererIndex</c> (:433-434),
    /// <c>UniversalRendererData.depthPrimingMode</c> (Runtime/UniversalRendererData.cs:251; Forced = 2),
    /// <c>ScriptableRendererData.rendererFeatures</c> and <c>SetDirty()</c> (Runtime/ScriptableRendererData.cs:58, :67),
    /// and the internal <c>ScreenSpaceAmbientOcclusion</c> feature with <c>m_Settings.AfterOpaque</c>
    /// (Runtime/RendererFeatures/ScreenSpaceAmbientOcclusion.cs:14, :65-69). A name that is not found ignores the test.
    /// </summary>
    sealed class UrpRendererOverride : IDisposable
    {
        const BindingFlags Public = BindingFlags.Public | BindingFlags.Instance;

        readonly RenderPipelineAsset _asset;
        ScriptableObject _renderer;
        PropertyInfo _msaa;
        object _oldMsaa;
        PropertyInfo _priming;
        object _oldPriming;
        IList _features;
        ScriptableObject _ssao;

        UrpRendererOverride(RenderPipelineAsset asset)
        {
            _asset = asset;
        }

        public static UrpRendererOverride Apply(bool depthPrimingForced, int msaaSamples, bool addSsaoAfterOpaque)
        {
            var change = new UrpRendererOverride(GraphicsSettings.currentRenderPipeline);
            try
            {
                change.Set(depthPrimingForced, msaaSamples, addSsaoAfterOpaque);
                return change;
            }
            catch
            {
                change.Dispose();
                throw;
            }
        }

        void Set(bool depthPrimingForced, int msaaSamples, bool addSsaoAfterOpaque)
        {
            _msaa = Require(_asset.GetType().GetProperty("msaaSampleCount", Public), "UniversalRenderPipelineAsset.msaaSampleCount");
            _oldMsaa = _msaa.GetValue(_asset);
            _msaa.SetValue(_asset, msaaSamples);

            var serialized = new SerializedObject(_asset);
            var list = serialized.FindProperty("m_RendererDataList");
            var index = serialized.FindProperty("m_DefaultRendererIndex");
            if (list == null || index == null || index.intValue >= list.arraySize) Assert.Ignore("this URP asset has no default renderer list");
            _renderer = list.GetArrayElementAtIndex(index.intValue).objectReferenceValue as ScriptableObject;
            if (_renderer == null || _renderer.GetType().Name != "UniversalRendererData")
                Assert.Ignore("the default renderer is not a Universal Renderer (" + (_renderer == null ? "none" : _renderer.GetType().Name) + ")");

            if (depthPrimingForced)
            {
                _priming = Require(_renderer.GetType().GetProperty("depthPrimingMode", Public), "UniversalRendererData.depthPrimingMode");
                _oldPriming = _priming.GetValue(_renderer);
                _priming.SetValue(_renderer, Enum.ToObject(_priming.PropertyType, 2)); // DepthPrimingMode.Forced
            }

            if (addSsaoAfterOpaque)
            {
                var ssaoType = Require(_renderer.GetType().Assembly.GetType("UnityEngine.Rendering.Universal.ScreenSpaceAmbientOcclusion"),
                    "UnityEngine.Rendering.Universal.ScreenSpaceAmbientOcclusion");
                _features = Require(_renderer.GetType().GetProperty("rendererFeatures", Public), "ScriptableRendererData.rendererFeatures")
                    .GetValue(_renderer) as IList;
                if (_features == null) Assert.Ignore("ScriptableRendererData.rendererFeatures is not a list");
                _ssao = ScriptableObject.CreateInstance(ssaoType);
                _ssao.name = "NeRF test SSAO";
                _ssao.hideFlags = HideFlags.HideAndDontSave;
                var settings = new SerializedObject(_ssao);
                var afterOpaque = settings.FindProperty("m_Settings.AfterOpaque");
                if (afterOpaque != null)
                {
                    afterOpaque.boolValue = true;
                    settings.ApplyModifiedPropertiesWithoutUndo();
                }
                _features.Add(_ssao);
            }
            MarkRendererDirty();
        }

        void MarkRendererDirty()
        {
            // ScriptableRendererData declares `public new void SetDirty()`, which makes URP rebuild the renderer.
            for (var type = _renderer.GetType(); type != null; type = type.BaseType)
            {
                var method = type.GetMethod("SetDirty", Public | BindingFlags.DeclaredOnly, null, Type.EmptyTypes, null);
                if (method == null) continue;
                method.Invoke(_renderer, null);
                return;
            }
        }

        static T Require<T>(T found, string name) where T : class
        {
            if (found == null) Assert.Ignore("this URP version has no " + name + ", which the test sets");
            return found;
        }

        public void Dispose()
        {
            if (_features != null && _ssao != null) _features.Remove(_ssao);
            if (_ssao != null) Object.DestroyImmediate(_ssao);
            if (_priming != null && _renderer != null) _priming.SetValue(_renderer, _oldPriming);
            if (_msaa != null && _oldMsaa != null) _msaa.SetValue(_asset, _oldMsaa);
            if (_renderer != null) MarkRendererDirty();
            _ssao = null;
            _features = null;
        }
    }
}
