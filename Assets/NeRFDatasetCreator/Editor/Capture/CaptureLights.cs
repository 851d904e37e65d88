using System;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// What makes a light copy in the preview scene light like the user's light. Copies have no lightmaps, so a copy that
    /// stays Baked (or Mixed) would light nothing (or only part of what it did): every copy is made realtime. URP keeps
    /// part of a light's settings on a separate component, copied by type name so that no URP assembly is referenced.
    /// </summary>
    static class CaptureLights
    {
        /// <summary>
        /// URP's per-light data (URP 14 <c>Runtime/UniversalAdditionalLightData.cs:57-218</c>): shadow bias from the
        /// pipeline or the light (<c>m_UsePipelineSettings</c>, read by <c>ShadowUtils.cs:537</c>), shadow resolution
        /// tier (<c>UniversalRenderPipeline.cs:1403-1425</c>), light layers and custom shadow layers
        /// (<c>ForwardLights.cs:482</c>), cookie size and offset (<c>LightCookieManager.cs:579</c>) and soft-shadow
        /// quality. URP reads it with GetComponent/TryGetComponent whether or not the component is enabled.
        /// </summary>
        public const string UrpLightDataTypeName = "UnityEngine.Rendering.Universal.UniversalAdditionalLightData";

        /// <summary>
        /// Makes <paramref name="light"/> a realtime light that was never baked: the bake setting (editor-only
        /// <c>Light.lightmapBakeType</c>) and the last bake's output (<c>Light.bakingOutput</c>, which the renderer
        /// reads and <c>Object.Instantiate</c> copies), set to what Unity itself writes for a light that is not
        /// lightmapped (UCR 2022.3 <c>Runtime/Export/Graphics/Light.deprecated.cs:40-47</c>).
        /// </summary>
        public static void MakeRealtime(Light light)
        {
            light.lightmapBakeType = LightmapBakeType.Realtime;
            light.bakingOutput = new LightBakingOutput
            {
                probeOcclusionLightIndex = -1,
                occlusionMaskChannel = -1,
                lightmapBakeType = LightmapBakeType.Realtime,
                mixedLightingMode = MixedLightingMode.IndirectOnly,
                isBaked = false,
            };
        }

        /// <summary>
        /// Copies the pipeline's per-light component (URP's <see cref="UrpLightDataTypeName"/>) from
        /// <paramref name="from"/> onto <paramref name="to"/>'s object with <c>EditorUtility.CopySerialized</c>: every
        /// serialized field, whatever the URP version holds. Returns false when the source has none (Built-in, or a
        /// light URP never touched: URP then adds one with defaults to the copy too, <c>ForwardLights.cs:482</c>).
        /// </summary>
        public static bool CopyPipelineData(Light from, Light to)
        {
            var source = FindByTypeName(from.gameObject, UrpLightDataTypeName);
            if (source == null) return false;
            var type = source.GetType();
            var destination = to.GetComponent(type);
            if (destination == null) destination = to.gameObject.AddComponent(type);
            if (destination == null) return false;
            EditorUtility.CopySerialized(source, destination);
            return true;
        }

        internal static Component FindByTypeName(GameObject gameObject, string fullName)
        {
            foreach (var component in gameObject.GetComponents<Component>())
                if (component != null && component.GetType().FullName == fullName) return component;
            return null;
        }

        /// <summary>Every light under <paramref name="root"/>: realtime; one that cannot be changed is logged and left.</summary>
        public static void MakeAllRealtime(GameObject root)
        {
            foreach (var light in root.GetComponentsInChildren<Light>(true))
            {
                try
                {
                    MakeRealtime(light);
                }
                catch (Exception e)
                {
                    Debug.LogWarning("NeRF Dataset Creator: the copy of the light '" + light.name + "' could not be made realtime " +
                        "and may light the capture differently: " + e.Message);
                }
            }
        }
    }
}
