using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// One of the package's hidden shaders, found and checked once per run (the data passes' and the material passes'):
    /// a missing or unsupported shader stops the capture with what to do.
    /// </summary>
    static class PackageShader
    {
        /// <remarks>
        /// Shader.Find sees every shader the editor imported, package shaders included: no Resources folder needed
        /// (docs: Shader.Find); Shader.isSupported is false when no SubShader runs on the graphics API (docs: Shader.isSupported).
        /// </remarks>
        public static Shader Find(string name)
        {
            var shader = Shader.Find(name);
            if (shader == null)
                throw new CaptureException("The shader '" + name + "' was not found: the package's Shaders folder is " +
                    "missing or failed to import. Reimport the NeRF Dataset Creator package.");
            if (!shader.isSupported)
                throw new CaptureException("The shader '" + name + "' does not run on this GPU or graphics API (" +
                    SystemInfo.graphicsDeviceType + "); check the Console for its compile errors.");
            return shader;
        }
    }
}
