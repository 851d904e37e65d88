using System;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// URP's Rendering Debugger material modes, driven from script. Implemented in the optional assembly
    /// <c>NerfDatasetCreator.Editor.Urp</c> (compiled only when URP 14–17 is installed: its asmdef's versionDefines),
    /// which registers itself in <see cref="UrpMaterialDebug.View"/> when the editor loads; so this assembly never
    /// references URP and the Built-in pipeline compiles without it.
    /// </summary>
    public interface IUrpMaterialDebugView
    {
        /// <summary>
        /// Saves every Rendering Debugger setting it will touch, turns lighting, validation, wireframe/overdraw and HDR
        /// debug views off and post-processing off; disposing the result restores them all, exactly.
        /// </summary>
        IDisposable Begin();

        /// <summary>Sets the material mode for the next camera renders (inside <see cref="Begin"/>).</summary>
        void Show(MaterialPassKind pass);
    }

    /// <summary>Where the URP assembly registers its <see cref="IUrpMaterialDebugView"/>; null without URP.</summary>
    public static class UrpMaterialDebug
    {
        public static IUrpMaterialDebugView View { get; set; }
    }
}
