using System;
using UnityEngine;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Capture
{
    /// <summary>The mask, depth and normal materials swapped onto the target's copies for the data passes.</summary>
    sealed class CaptureMaterials : IDisposable
    {
        public const string MaskShaderName = "Hidden/NerfDatasetCreator/Mask";
        public const string DepthShaderName = "Hidden/NerfDatasetCreator/Depth";
        public const string NormalShaderName = "Hidden/NerfDatasetCreator/Normal";

        public Material Mask { get; private set; }
        public Material Depth { get; private set; }
        public Material Normal { get; private set; }

        public CaptureMaterials()
        {
            try
            {
                Mask = Create(MaskShaderName);
                Depth = Create(DepthShaderName);
                Normal = Create(NormalShaderName);
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        static Material Create(string shaderName)
        {
            // Shader.Find sees every shader the editor imported, package shaders included: no Resources folder needed.
            var shader = Shader.Find(shaderName);
            if (shader == null)
                throw new CaptureException("The shader '" + shaderName + "' was not found: the package's Shaders folder is " +
                    "missing or failed to import. Reimport the NeRF Dataset Creator package.");
            if (!shader.isSupported)
                throw new CaptureException("The shader '" + shaderName + "' does not run on this GPU or graphics API (" +
                    SystemInfo.graphicsDeviceType + "); check the Console for its compile errors.");
            return new Material(shader) { name = shaderName, hideFlags = HideFlags.HideAndDontSave };
        }

        public void Dispose()
        {
            if (Mask != null) Object.DestroyImmediate(Mask);
            if (Depth != null) Object.DestroyImmediate(Depth);
            if (Normal != null) Object.DestroyImmediate(Normal);
            Mask = Depth = Normal = null;
        }
    }
}
