using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Switches the lighting to one relighting render (<see cref="UnityLightingRender"/>) and, on <see cref="Dispose"/>,
    /// back to exactly what it was (<see cref="LightingState"/>), whatever happened in between. During a capture it is
    /// applied inside the preview-scene lighting override (<see cref="CaptureStage.PinLighting"/>), so RenderSettings
    /// address the capture's preview scene and the lights are the capture's copies: the user's scene is never touched.
    /// <list type="bullet">
    /// <item>Environment: <c>RenderSettings.skybox</c> = a Skybox/Cubemap (for a Cubemap asset) or Skybox/Panoramic
    /// (latitude-longitude, for a 2D texture) material made here, with <c>_Rotation</c> = the render's skybox rotation and
    /// <c>_Exposure</c>/<c>_Tint</c> giving a linear gain of exactly <c>Intensity</c> (Skybox-Panoramic.shader <c>frag</c>:
    /// <c>c * _Tint.rgb * unity_ColorSpaceDouble.rgb * _Exposure</c>, <c>_Exposure</c> declared <c>[Gamma]</c>);
    /// ambient from the sky (<c>AmbientMode.Skybox</c>, then <c>DynamicGI.UpdateEnvironment()</c>, UCR 2022.3.76f1 and
    /// 6000.0.78f1 <c>Runtime/Export/GI/DynamicGI.bindings.cs:23</c>: "Schedules an update of the environment cubemap");
    /// default reflection = the cubemap itself (<c>DefaultReflectionMode.Custom</c>) for a Cubemap, the sky for a 2D map.
    /// Every light is switched off.</item>
    /// <item>Point / spot: every light off, ambient black (Flat black colours, a zero SH probe, reflection intensity 0),
    /// and one new realtime Light under <paramref name="parent"/> at the render's position, colour, intensity, cone
    /// and shadows.</item>
    /// </list>
    /// </summary>
    public sealed class LightingSwitch : IDisposable
    {
        // UnityCG.cginc: unity_ColorSpaceDouble = (4.59479380, …) in Linear colour space, (2, …) in Gamma.
        const float LinearColorSpaceDouble = 4.59479380f;

        readonly LightingState _saved;
        Material _skybox;
        GameObject _light;
        bool _disposed;

        LightingSwitch(LightingState saved)
        {
            _saved = saved;
        }

        /// <param name="lights">Every light that may light the scene rendered (all are switched off).</param>
        /// <param name="parent">Where a point or spot light is created (the capture's root, in its preview scene).</param>
        /// <param name="range">The range given to a point or spot light (Unity units): it must reach the whole target.</param>
        public static LightingSwitch Apply(UnityLightingRender render, IReadOnlyList<Light> lights, Transform parent, float range)
        {
            var change = new LightingSwitch(new LightingState(lights));
            try
            {
                foreach (var light in lights)
                    if (light != null) light.enabled = false;
                if (render.Kind == LightingKind.Environment) change.Environment(render);
                else change.OneLight(render, parent, range);
                return change;
            }
            catch
            {
                change.Dispose();
                throw;
            }
        }

        void Environment(UnityLightingRender render)
        {
            var texture = AssetDatabase.LoadAssetAtPath<Texture>(render.File);
            if (texture == null)
                throw new CaptureException("relighting: the environment map '" + render.File + "' (" + render.Key + ") is not a texture in this project. " +
                    "Give the project path of an HDR cubemap or equirectangular texture, e.g. \"Assets/HDRI/sunset.exr\".");
            var cube = texture as Cubemap;
            var shaderName = cube != null ? "Skybox/Cubemap" : "Skybox/Panoramic";
            var shader = Shader.Find(shaderName);
            if (shader == null) throw new CaptureException("relighting: Unity's built-in shader '" + shaderName + "' was not found.");
            _skybox = new Material(shader) { name = "NeRF relighting " + render.Key, hideFlags = HideFlags.HideAndDontSave };
            _skybox.SetTexture(cube != null ? "_Tex" : "_MainTex", texture);
            _skybox.SetFloat("_Rotation", (float)render.SkyboxRotationDegrees);
            var linear = QualitySettings.activeColorSpace == ColorSpace.Linear;
            // Linear gain = Intensity: _Tint (a Color, linearised by Unity) × unity_ColorSpaceDouble = 1, and
            // _Exposure ([Gamma], linearised by Unity) = Intensity.
            var tint = linear ? Mathf.LinearToGammaSpace(1f / LinearColorSpaceDouble) : 0.5f;
            _skybox.SetColor("_Tint", new Color(tint, tint, tint, 1f));
            _skybox.SetFloat("_Exposure", linear ? Mathf.LinearToGammaSpace((float)render.Intensity) : (float)render.Intensity);
            RenderSettings.skybox = _skybox;
            RenderSettings.ambientMode = AmbientMode.Skybox;
            RenderSettings.ambientIntensity = 1f;
            RenderSettings.reflectionIntensity = 1f;
            if (cube != null)
            {
                RenderSettings.defaultReflectionMode = DefaultReflectionMode.Custom;
                RenderSettings.customReflectionTexture = cube;
            }
            else
            {
                RenderSettings.defaultReflectionMode = DefaultReflectionMode.Skybox;
            }
            DynamicGI.UpdateEnvironment();
        }

        void OneLight(UnityLightingRender render, Transform parent, float range)
        {
            RenderSettings.ambientMode = AmbientMode.Flat;
            RenderSettings.ambientSkyColor = Color.black;
            RenderSettings.ambientEquatorColor = Color.black;
            RenderSettings.ambientGroundColor = Color.black;
            RenderSettings.ambientProbe = new SphericalHarmonicsL2(); // all zero: no ambient
            RenderSettings.reflectionIntensity = 0f;
            _light = new GameObject("NeRF relighting " + render.Key) { hideFlags = HideFlags.HideAndDontSave };
            if (parent != null) _light.transform.SetParent(parent, false);
            var light = _light.AddComponent<Light>();
            light.type = render.Kind == LightingKind.Spot ? LightType.Spot : LightType.Point;
            light.lightmapBakeType = LightmapBakeType.Realtime;
            _light.transform.position = new Vector3((float)render.Position.X, (float)render.Position.Y, (float)render.Position.Z);
            if (render.Kind == LightingKind.Spot)
            {
                _light.transform.rotation = Quaternion.LookRotation(new Vector3((float)render.Direction.X, (float)render.Direction.Y, (float)render.Direction.Z));
                light.spotAngle = (float)render.SpotAngle;
            }
            // Light.color is an sRGB colour that Unity linearises in a Linear project: give it the gamma encoding of the
            // linear colour asked for.
            var colour = new Color((float)render.Colour[0], (float)render.Colour[1], (float)render.Colour[2], 1f);
            light.color = QualitySettings.activeColorSpace == ColorSpace.Linear ? colour.gamma : colour;
            light.intensity = (float)render.Intensity;
            light.range = range;
            light.shadows = render.Shadows ? LightShadows.Soft : LightShadows.None;
        }

        /// <summary>Restores every setting and light, and destroys what <see cref="Apply"/> made. Never throws twice.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            try
            {
                _saved.Restore();
            }
            finally
            {
                if (_light != null) Object.DestroyImmediate(_light);
                if (_skybox != null) Object.DestroyImmediate(_skybox);
                _light = null;
                _skybox = null;
            }
        }
    }
}
