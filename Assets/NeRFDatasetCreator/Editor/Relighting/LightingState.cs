using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Every lighting setting a relighting condition changes (<see cref="LightingSwitch"/>), as it was: the
    /// <c>RenderSettings</c> fields below, in whichever scene they address now (during a capture, the preview scene's,
    /// pinned by <see cref="SceneLighting"/>), and each given light's <c>enabled</c>. <see cref="Restore"/> writes them
    /// all back. RenderSettings members as declared in UCR 2022.3.76f1 and 6000.0.78f1
    /// <c>Runtime/Export/Graphics/GraphicsManagers.bindings.cs:47-58</c> (ambient mode, colours, intensity, skybox,
    /// ambient probe) and <c>:73-80</c> (customReflectionTexture, reflectionIntensity, defaultReflectionMode), the same
    /// lines in both.
    /// </summary>
    public sealed class LightingState
    {
        readonly Material _skybox;
        readonly AmbientMode _ambientMode;
        readonly Color _sky, _equator, _ground;
        readonly float _ambientIntensity, _reflectionIntensity;
        readonly SphericalHarmonicsL2 _ambientProbe;
        readonly DefaultReflectionMode _reflectionMode;
        readonly Texture _customReflection;
        readonly List<KeyValuePair<Light, bool>> _lights = new List<KeyValuePair<Light, bool>>();

        public LightingState(IEnumerable<Light> lights)
        {
            _skybox = RenderSettings.skybox;
            _ambientMode = RenderSettings.ambientMode;
            _sky = RenderSettings.ambientSkyColor;
            _equator = RenderSettings.ambientEquatorColor;
            _ground = RenderSettings.ambientGroundColor;
            _ambientIntensity = RenderSettings.ambientIntensity;
            _ambientProbe = RenderSettings.ambientProbe;
            _reflectionMode = RenderSettings.defaultReflectionMode;
            _customReflection = RenderSettings.customReflectionTexture;
            _reflectionIntensity = RenderSettings.reflectionIntensity;
            if (lights != null)
                foreach (var light in lights)
                    if (light != null) _lights.Add(new KeyValuePair<Light, bool>(light, light.enabled));
        }

        /// <summary>The lights recorded, with the <c>enabled</c> each had.</summary>
        public IReadOnlyList<KeyValuePair<Light, bool>> Lights => _lights;

        /// <summary>Writes every recorded value back (a light destroyed since is skipped).</summary>
        public void Restore()
        {
            RenderSettings.skybox = _skybox;
            RenderSettings.ambientMode = _ambientMode;
            RenderSettings.ambientSkyColor = _sky;
            RenderSettings.ambientEquatorColor = _equator;
            RenderSettings.ambientGroundColor = _ground;
            RenderSettings.ambientIntensity = _ambientIntensity;
            // Last among the ambient fields: changing the mode or colours may make Unity recompute the probe.
            RenderSettings.ambientProbe = _ambientProbe;
            RenderSettings.defaultReflectionMode = _reflectionMode;
            RenderSettings.customReflectionTexture = _customReflection;
            RenderSettings.reflectionIntensity = _reflectionIntensity;
            foreach (var pair in _lights)
                if (pair.Key != null) pair.Key.enabled = pair.Value;
        }

        /// <summary>The first recorded value that differs from <paramref name="other"/>'s, named; null when all are equal.</summary>
        public string FirstDifference(LightingState other)
        {
            if (_skybox != other._skybox) return "skybox";
            if (_ambientMode != other._ambientMode) return "ambientMode";
            if (_sky != other._sky) return "ambientSkyColor";
            if (_equator != other._equator) return "ambientEquatorColor";
            if (_ground != other._ground) return "ambientGroundColor";
            if (_ambientIntensity != other._ambientIntensity) return "ambientIntensity";
            if (_ambientProbe != other._ambientProbe) return "ambientProbe";
            if (_reflectionMode != other._reflectionMode) return "defaultReflectionMode";
            if (_customReflection != other._customReflection) return "customReflectionTexture";
            if (_reflectionIntensity != other._reflectionIntensity) return "reflectionIntensity";
            if (_lights.Count != other._lights.Count) return "the number of lights";
            for (var i = 0; i < _lights.Count; i++)
                if (_lights[i].Key != other._lights[i].Key || _lights[i].Value != other._lights[i].Value)
                    return "light '" + (_lights[i].Key == null ? "(destroyed)" : _lights[i].Key.name) + "' enabled";
            return null;
        }
    }
}
