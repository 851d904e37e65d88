using System;
using UnityEditor;
using UnityEngine.Rendering.Universal;

namespace NerfDatasetCreator.Editor.Urp
{
    /// <summary>
    /// URP's Rendering Debugger material modes for the material passes (issue 38). Everything here is public URP API,
    /// verified in URP 14.0.8 (devagame/URP-14-Extension 1ec2498d, <c>Packages/com.unity.render-pipelines.universal@14.0.8/</c>)
    /// and URP 17.0.3 (WxKnight/Unity6Demo dd3d333, Unity 6000.0):
    /// <list type="bullet">
    /// <item><c>UniversalRenderPipelineDebugDisplaySettings.Instance</c>: the one settings object every renderer's
    /// DebugHandler reads (Core RP 14 <c>Runtime/Debugging/DebugDisplaySettings.cs:28</c>; URP 14
    /// <c>Runtime/Debug/DebugHandler.cs:134</c>), with <c>materialSettings</c>, <c>renderingSettings</c>,
    /// <c>lightingSettings</c> (<c>Runtime/Debug/UniversalRenderPipelineDebugDisplaySettings.cs:15,20,25</c>, same lines in 17).</item>
    /// <item><c>DebugDisplaySettingsMaterial.materialDebugMode</c> (<c>DebugDisplaySettingsMaterial.cs:263</c>, 17: :263);
    /// any mode other than None makes <c>IsPostProcessingAllowed</c> and <c>IsLightingActive</c> false (:451-460).</item>
    /// <item><c>DebugMaterialMode</c> Albedo / Specular / Smoothness / Emission / Metallic
    /// (<c>ShaderLibrary/Debug/DebugViewEnums.cs:11-37</c>), which <c>Debugging3D.hlsl:116-163</c> turns into
    /// <c>half4(surfaceData.albedo, 1)</c>, <c>surfaceData.specular</c>, <c>surfaceData.smoothness.rrr</c>,
    /// <c>surfaceData.emission</c>, <c>surfaceData.metallic.rrr</c> (17.0.3: :142-175). Fog is off in every
    /// material mode (<c>DebuggingCommon.hlsl:130-140</c>).</item>
    /// <item>The debug view is active for every camera but Preview cameras (<c>DebugHandler.cs:151-153</c>; 17: :193-196):
    /// the capture camera is a Game camera.</item>
    /// </list>
    /// The values are the shader's own, in the project's colour space: linear in a Linear project (the Lit shader's colour
    /// properties are linearised by Unity, sRGB textures by the sampler), gamma-space in a Gamma project, where the
    /// capture decodes colours with the sRGB curve. 6000.0 (URP 17) has the same API; it differs only in line numbers and
    /// in <c>DebugHandler.IsActiveForCamera(bool)</c>'s signature, which this code does not call.
    /// </summary>
    [InitializeOnLoad]
    sealed class UrpMaterialDebugView : IUrpMaterialDebugView
    {
        static UrpMaterialDebugView()
        {
            UrpMaterialDebug.View = new UrpMaterialDebugView();
        }

        public IDisposable Begin() => new SavedSettings();

        public void Show(MaterialPassKind pass)
        {
            UniversalRenderPipelineDebugDisplaySettings.Instance.materialSettings.materialDebugMode = ModeOf(pass);
        }

        /// <summary>The Rendering Debugger mode of each pass (DebugViewEnums.cs:11-37).</summary>
        internal static DebugMaterialMode ModeOf(MaterialPassKind pass)
        {
            switch (pass)
            {
                case MaterialPassKind.Albedo: return DebugMaterialMode.Albedo;
                case MaterialPassKind.Metallic: return DebugMaterialMode.Metallic;
                case MaterialPassKind.Smoothness: return DebugMaterialMode.Smoothness;
                case MaterialPassKind.Specular: return DebugMaterialMode.Specular;
                case MaterialPassKind.Emission: return DebugMaterialMode.Emission;
                default: throw new ArgumentOutOfRangeException(nameof(pass), pass, null);
            }
        }

        /// <summary>
        /// The user's Rendering Debugger settings that could change a material mode's output: the lighting debug modes
        /// replace SurfaceData (<c>Debugging3D.hlsl:32-77</c>), validation and wireframe/overdraw take precedence
        /// (<c>:165-183</c>), the HDR debug view rewrites the final target, and post-processing "Enabled" would run
        /// post on the passes (<c>UniversalRenderPipelineDebugDisplaySettings.cs:43-76</c>). Restored on Dispose.
        /// (<c>DebugDisplaySettingsRendering.mipInfoMode</c> is internal in both versions and cannot be saved; see the
        /// maintainers' page.)
        /// </summary>
        sealed class SavedSettings : IDisposable
        {
            readonly DebugMaterialMode _material;
            readonly DebugVertexAttributeMode _vertex;
            readonly DebugMaterialValidationMode _validation;
            readonly DebugLightingMode _lighting;
            readonly DebugLightingFeatureFlags _features;
            readonly HDRDebugMode _hdr;
            readonly DebugWireframeMode _wireframe;
            readonly DebugOverdrawMode _overdraw;
            readonly DebugPostProcessingMode _post;
            bool _disposed;

            public SavedSettings()
            {
                var s = UniversalRenderPipelineDebugDisplaySettings.Instance;
                _material = s.materialSettings.materialDebugMode;
                _vertex = s.materialSettings.vertexAttributeDebugMode;
                _validation = s.materialSettings.materialValidationMode;
                _lighting = s.lightingSettings.lightingDebugMode;
                _features = s.lightingSettings.lightingFeatureFlags;
                _hdr = s.lightingSettings.hdrDebugMode;
                _wireframe = s.renderingSettings.wireframeMode;
                _overdraw = s.renderingSettings.overdrawMode;
                _post = s.renderingSettings.postProcessingDebugMode;

                s.materialSettings.vertexAttributeDebugMode = DebugVertexAttributeMode.None;
                s.materialSettings.materialValidationMode = DebugMaterialValidationMode.None;
                s.lightingSettings.lightingDebugMode = DebugLightingMode.None;
                s.lightingSettings.lightingFeatureFlags = DebugLightingFeatureFlags.None;
                s.lightingSettings.hdrDebugMode = HDRDebugMode.None;
                s.renderingSettings.wireframeMode = DebugWireframeMode.None;
                s.renderingSettings.overdrawMode = DebugOverdrawMode.None;
                s.renderingSettings.postProcessingDebugMode = DebugPostProcessingMode.Disabled;
            }

            public void Dispose()
            {
                if (_disposed) return;
                _disposed = true;
                var s = UniversalRenderPipelineDebugDisplaySettings.Instance;
                s.materialSettings.materialDebugMode = _material;
                s.materialSettings.vertexAttributeDebugMode = _vertex;
                s.materialSettings.materialValidationMode = _validation;
                s.lightingSettings.lightingDebugMode = _lighting;
                s.lightingSettings.lightingFeatureFlags = _features;
                s.lightingSettings.hdrDebugMode = _hdr;
                s.renderingSettings.wireframeMode = _wireframe;
                s.renderingSettings.overdrawMode = _overdraw;
                s.renderingSettings.postProcessingDebugMode = _post;
            }
        }
    }
}
