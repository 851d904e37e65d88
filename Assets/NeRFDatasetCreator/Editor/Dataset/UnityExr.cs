using UnityEngine;
using UnityEngine.Experimental.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Core's EXR encoder, backed by Unity's thread-safe ImageConversion.EncodeArrayToEXR.</summary>
    static class UnityExr
    {
        /// <summary>32-bit float, ZIP-compressed (as Perception writes depth); rows in texture order (bottom-up).</summary>
        public static byte[] Encode(float[] pixels, int width, int height, int channels) =>
            ImageConversion.EncodeArrayToEXR(pixels,
                channels == 1 ? GraphicsFormat.R32_SFloat : GraphicsFormat.R32G32B32A32_SFloat,
                (uint)width, (uint)height, 0, Texture2D.EXRFlags.OutputAsFloat | Texture2D.EXRFlags.CompressZIP);
    }
}
