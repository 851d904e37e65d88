// Compile-check stub of URP 14.0.8 (devagame/URP-14-Extension, Packages/com.unity.render-pipelines.universal@14.0.8/):
// the signatures NerfDatasetCreator.Editor.Urp uses, with no behaviour. Never shipped. URP 17.0.3 has the same members.
namespace UnityEngine.Rendering.Universal
{
    // Runtime/Debug/UniversalRenderPipelineDebugDisplaySettings.cs:8 (derives from DebugDisplaySettings<T>, whose
    // static Instance is Core RP Runtime/Debugging/DebugDisplaySettings.cs:28; declared here, see the Core stub).
    public class UniversalRenderPipelineDebugDisplaySettings
    {
        public static UniversalRenderPipelineDebugDisplaySettings Instance => throw new System.NotSupportedException("compile-check stub");
        public DebugDisplaySettingsMaterial materialSettings { get; private set; } // :15
        public DebugDisplaySettingsRendering renderingSettings { get; private set; } // :20
        public DebugDisplaySettingsLighting lightingSettings { get; private set; } // :25
    }

    // Runtime/Debug/DebugDisplaySettingsMaterial.cs:10
    public class DebugDisplaySettingsMaterial
    {
        public DebugMaterialValidationMode materialValidationMode { get; set; } // :256
        public DebugMaterialMode materialDebugMode { get; set; } // :263
        public DebugVertexAttributeMode vertexAttributeDebugMode { get; set; } // :268
    }

    // Runtime/Debug/DebugDisplaySettingsLighting.cs:10
    public class DebugDisplaySettingsLighting
    {
        public DebugLightingMode lightingDebugMode { get; set; } // :15
        public DebugLightingFeatureFlags lightingFeatureFlags { get; set; } // :20
        public HDRDebugMode hdrDebugMode { get; set; } // :25
    }

    // Runtime/Debug/DebugDisplaySettingsRendering.cs:11 and :26
    public enum DebugWireframeMode { None, Wireframe, SolidWireframe, ShadedWireframe }

    public class DebugDisplaySettingsRendering
    {
        public DebugWireframeMode wireframeMode { get; set; } // :36
        public DebugOverdrawMode overdrawMode { get; set; } // :68
        public DebugPostProcessingMode postProcessingDebugMode { get; set; } // :120 (17.0.3: :166)
    }

    // ShaderLibrary/Debug/DebugViewEnums.cs (values in declaration order, as there)
    public enum DebugMaterialMode { None, Albedo, Specular, Alpha, Smoothness, AmbientOcclusion, Emission, NormalWorldSpace, NormalTangentSpace, LightingComplexity, Metallic, SpriteMask } // :11-37
    public enum DebugVertexAttributeMode { None, Texcoord0, Texcoord1, Texcoord2, Texcoord3, Color, Tangent, Normal } // :43-61
    public enum DebugMaterialValidationMode { None, Albedo, Metallic } // :67-75
    public enum DebugOverdrawMode { None, Opaque, Transparent, All } // :123-133
    public enum DebugPostProcessingMode { Disabled, Auto, Enabled } // :158
    public enum DebugLightingMode { None } // :215 (only None is used)
    public enum HDRDebugMode { None } // :235 (only None is used)
    [System.Flags] public enum DebugLightingFeatureFlags { None } // :251-254 (only None is used)
}
