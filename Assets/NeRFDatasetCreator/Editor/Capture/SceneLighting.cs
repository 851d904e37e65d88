using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The environment lighting of the user's active scene (ambient, default reflection, fog), read once when a capture
    /// starts and pinned onto the preview scene while each view renders. Unity's own previews do the same:
    /// <c>PreviewRenderUtility</c> calls <c>Unsupported.SetOverrideLightingSettings(previewScene)</c>, then writes
    /// <c>RenderSettings</c> (which then address the preview scene's settings), renders, and calls
    /// <c>Unsupported.RestoreOverrideLightingSettings()</c> (UCR 2022.3 <c>Editor/Mono/Inspector/PreviewRenderUtility.cs:249-255</c>,
    /// <c>:380</c>, <c>:520-525</c>; both calls public in 2022.3 and 6000.0, <c>Editor/Mono/Unsupported.bindings.cs:114-123</c>).
    /// Without the override a preview scene renders with lighting settings Unity does not document.
    /// </summary>
    sealed class SceneLighting
    {
        readonly AmbientMode _ambientMode;
        readonly Color _sky, _equator, _ground, _subtractiveShadow, _fogColor;
        readonly float _ambientIntensity, _reflectionIntensity, _fogDensity, _fogStart, _fogEnd;
        readonly SphericalHarmonicsL2 _ambientProbe;
        readonly Texture _reflection;
        readonly bool _fog;
        readonly FogMode _fogMode;
        bool _overridden;

        /// <summary>Reads the active scene's settings (RenderSettings address the active scene when no override is set).</summary>
        public SceneLighting()
        {
            _ambientMode = RenderSettings.ambientMode;
            _sky = RenderSettings.ambientSkyColor;
            _equator = RenderSettings.ambientEquatorColor;
            _ground = RenderSettings.ambientGroundColor;
            _ambientIntensity = RenderSettings.ambientIntensity;
            _ambientProbe = RenderSettings.ambientProbe;
            _subtractiveShadow = RenderSettings.subtractiveShadowColor;
            // The environment reflection Unity generated for the active scene; PreviewRenderUtility.BeginPreview reads it
            // before overriding (:249) and sets it as the preview scene's custom reflection (:253-254). So do we.
            _reflection = ReflectionProbe.defaultTexture;
            _reflectionIntensity = RenderSettings.reflectionIntensity;
            _fog = RenderSettings.fog;
            _fogMode = RenderSettings.fogMode;
            _fogColor = RenderSettings.fogColor;
            _fogDensity = RenderSettings.fogDensity;
            _fogStart = RenderSettings.fogStartDistance;
            _fogEnd = RenderSettings.fogEndDistance;
        }

        /// <summary>
        /// Makes <paramref name="preview"/>'s lighting settings the ones rendered with and fills them with the user's.
        /// Skipped while the editor imports assets, as PreviewRenderUtility does (<c>!EditorApplication.isUpdating</c>).
        /// </summary>
        public void Pin(Scene preview)
        {
            if (_overridden || EditorApplication.isUpdating || !Unsupported.SetOverrideLightingSettings(preview)) return;
            _overridden = true;
            RenderSettings.ambientMode = _ambientMode;
            RenderSettings.ambientSkyColor = _sky;
            RenderSettings.ambientEquatorColor = _equator;
            RenderSettings.ambientGroundColor = _ground;
            RenderSettings.ambientIntensity = _ambientIntensity;
            // Skybox ambient is a probe the GI system computed for the user's scene from its sky ("Skybox ambient
            // lighting mode uses this SH probe"; "you can also assign a completely custom SH probe this way",
            // Scripting API RenderSettings.ambientProbe). Flat and Trilight are computed from the colours above.
            if (_ambientMode == AmbientMode.Skybox) RenderSettings.ambientProbe = _ambientProbe;
            RenderSettings.subtractiveShadowColor = _subtractiveShadow;
            if (_reflection != null)
            {
                RenderSettings.defaultReflectionMode = DefaultReflectionMode.Custom;
                RenderSettings.customReflectionTexture = _reflection;
            }
            RenderSettings.reflectionIntensity = _reflectionIntensity;
            RenderSettings.fog = _fog;
            RenderSettings.fogMode = _fogMode;
            RenderSettings.fogColor = _fogColor;
            RenderSettings.fogDensity = _fogDensity;
            RenderSettings.fogStartDistance = _fogStart;
            RenderSettings.fogEndDistance = _fogEnd;
        }

        /// <summary>Gives the editor its own lighting settings back (the Scene view renders between capture slices).</summary>
        public void Unpin()
        {
            if (!_overridden) return;
            _overridden = false;
            Unsupported.RestoreOverrideLightingSettings();
        }
    }
}
