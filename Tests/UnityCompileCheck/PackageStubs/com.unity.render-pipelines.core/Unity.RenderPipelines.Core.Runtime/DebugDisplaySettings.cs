// Compile-check stub of com.unity.render-pipelines.core 14.0.8, Runtime/Debugging/DebugDisplaySettings.cs. The real
// UniversalRenderPipelineDebugDisplaySettings derives from DebugDisplaySettings<T> (whose static Instance, :28, the
// plugin calls); a stub assembly cannot reference another stub, so the URP stub declares Instance itself and this one
// only exists so that the asmdef's reference resolves. Never shipped.
namespace UnityEngine.Rendering
{
    public interface IDebugDisplaySettings // Runtime/Debugging/IDebugDisplaySettings.cs
    {
    }
}
