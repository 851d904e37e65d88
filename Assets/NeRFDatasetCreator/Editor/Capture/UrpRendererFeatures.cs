using System;
using System.Collections;
using System.Collections.Generic;
using System.Reflection;
using UnityEngine;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Reads, by reflection (no URP assembly is referenced, so the package compiles and runs without URP), the renderer
    /// features of the renderer the capture camera renders with, and the pipeline's GPU Resident Drawer settings.
    /// <para>
    /// Which renderer: the capture camera has no <c>UniversalAdditionalCameraData</c> (a template's <c>CopyFrom</c>
    /// copies the Camera only), so URP gives it one with <c>m_RendererIndex = -1</c> (URP 14.0.8
    /// <c>Runtime/UniversalAdditionalCameraData.cs:316</c>), which selects the asset's default renderer
    /// (<c>scriptableRenderer</c>, <c>:517-525</c>; <c>UniversalRenderPipelineAsset.GetRenderer</c>,
    /// <c>Runtime/Data/UniversalRenderPipelineAsset.cs:886-889</c>). The asset's renderer list and default index are the
    /// internal fields <c>m_RendererDataList</c> and <c>m_DefaultRendererIndex</c> (URP 14.0.8 <c>:433-434</c>, URP 17.0.3
    /// <c>:461-462</c>), and its internal <c>scriptableRendererData</c> property returns that entry (URP 14 <c>:917-925</c>,
    /// URP 17 <c>:928</c>). A renderer's features are the public <c>ScriptableRendererData.rendererFeatures</c>
    /// (URP 14 <c>Runtime/ScriptableRendererData.cs:58</c>, URP 17 <c>:35</c>), each with the public
    /// <c>ScriptableRendererFeature.isActive</c> (<c>Runtime/ScriptableRendererFeature.cs:18</c> in both).
    /// </para>
    /// </summary>
    public static class UrpRendererFeatures
    {
        const BindingFlags AnyInstance = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance;

        /// <summary>
        /// The default renderer's features (null for the Built-in pipeline or a pipeline without renderer data) and the
        /// renderer's asset name as <paramref name="rendererName"/>.
        /// </summary>
        public static List<RendererFeatureInfo> Read(out string rendererName)
        {
            rendererName = null;
            var data = DefaultRendererData(GraphicsSettings.currentRenderPipeline);
            if (data == null) return null;
            rendererName = data is UnityEngine.Object asset ? "\"" + asset.name + "\"" : data.GetType().Name;
            var features = new List<RendererFeatureInfo>();
            if (!(data.GetType().GetProperty("rendererFeatures", BindingFlags.Public | BindingFlags.Instance)?.GetValue(data) is IEnumerable list))
                return features;
            foreach (var feature in list)
            {
                // A missing script leaves a null entry, which URP skips too.
                if (feature == null || (feature is UnityEngine.Object o && o == null)) continue;
                var names = new List<string>();
                for (var type = feature.GetType(); type != null && type != typeof(ScriptableObject); type = type.BaseType) names.Add(type.Name);
                var active = feature.GetType().GetProperty("isActive", BindingFlags.Public | BindingFlags.Instance)?.GetValue(feature) as bool? ?? true;
                features.Add(new RendererFeatureInfo((feature as UnityEngine.Object)?.name ?? feature.GetType().Name, names, active));
            }
            return features;
        }

        /// <summary>The asset's default renderer data: the fields first (no side effects), the internal property otherwise.</summary>
        static object DefaultRendererData(RenderPipelineAsset asset)
        {
            if (asset == null) return null;
            var type = asset.GetType();
            if (type.GetField("m_RendererDataList", AnyInstance)?.GetValue(asset) is IList list
                && type.GetField("m_DefaultRendererIndex", AnyInstance)?.GetValue(asset) is int index
                && index >= 0 && index < list.Count && list[index] != null)
                return list[index];
            try
            {
                return type.GetProperty("scriptableRendererData", AnyInstance)?.GetValue(asset);
            }
            catch (TargetInvocationException)
            {
                return null;
            }
        }

        /// <summary>
        /// Unity 6's GPU Resident Drawer with occlusion culling in cameras (URP 17.0.3: the asset's public
        /// <c>gpuResidentDrawerMode</c> and <c>gpuResidentDrawerEnableOcclusionCullingInCameras</c>,
        /// <c>Runtime/Data/UniversalRenderPipelineAsset.cs:1637-1653</c>; URP turns the culling on for Game cameras,
        /// <c>UniversalRenderPipeline.cs:1506-1508</c>): a warning, since the capture camera jumps between poses and the
        /// occluders it culls with come from the previous view. Null when off or absent (URP 14 has neither).
        /// </summary>
        public static ValidationProblem GpuOcclusionCullingWarning()
        {
            var asset = GraphicsSettings.currentRenderPipeline;
            if (asset == null) return null;
            var type = asset.GetType();
            var mode = type.GetProperty("gpuResidentDrawerMode", BindingFlags.Public | BindingFlags.Instance)?.GetValue(asset);
            var occlusion = type.GetProperty("gpuResidentDrawerEnableOcclusionCullingInCameras", BindingFlags.Public | BindingFlags.Instance)?.GetValue(asset) as bool?;
            if (mode == null || Convert.ToInt32(mode) == 0 || occlusion != true) return null;
            return new ValidationProblem("renderer", asset.name,
                "uses the GPU Resident Drawer with occlusion culling in cameras. The capture camera jumps from pose to pose, so " +
                "the occluders it culls with come from the previous view: objects could be missing from the colour images " +
                "(this has not been verified in a Unity Editor).",
                "Untick GPU Occlusion Culling (or set GPU Resident Drawer to Disabled) in " + asset.name + " for the capture.");
        }
    }
}
