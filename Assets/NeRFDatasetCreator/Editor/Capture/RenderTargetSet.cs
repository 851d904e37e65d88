using System;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The render textures one view renders into. A capture keeps one set per readback in flight, so that no texture
    /// is rendered into while a readback of it is pending.
    /// </summary>
    sealed class RenderTargetSet : IDisposable
    {
        /// <summary>The colour pass over a black clear; with <see cref="ColorOverWhite"/>, the difference-matting pair.</summary>
        public RenderTexture ColorOverBlack { get; private set; }
        public RenderTexture ColorOverWhite { get; private set; }
        public RenderTexture Mask { get; private set; }
        public RenderTexture Depth { get; private set; }
        public RenderTexture Normal { get; private set; }

        /// <summary>The labels pass (<see cref="CapturePasses.Labels"/>), at the colour's supersampled size: one id pair per sample.</summary>
        public RenderTexture Labels { get; private set; }

        public RenderTargetSet(CaptureOptions options, CapturePasses passes, int index)
        {
            try
            {
                int w = options.SupersampledWidth, h = options.SupersampledHeight;
                int dw = options.DataWidth, dh = options.DataHeight;
                var suffix = " " + index;
                if ((passes & CapturePasses.Color) != 0)
                {
                    ColorOverBlack = Create(w, h, CaptureEnvironment.ColorFormat, "NeRF colour over black" + suffix);
                    ColorOverWhite = Create(w, h, CaptureEnvironment.ColorFormat, "NeRF colour over white" + suffix);
                }
                if ((passes & CapturePasses.Mask) != 0)
                    Mask = Create(w, h, CaptureEnvironment.MaskFormat, "NeRF mask" + suffix);
                if ((passes & CapturePasses.Depth) != 0)
                    Depth = Create(dw, dh, CaptureEnvironment.DepthFormat, "NeRF depth" + suffix);
                if ((passes & CapturePasses.Normal) != 0)
                    Normal = Create(dw, dh, CaptureEnvironment.NormalFormat, "NeRF normal" + suffix);
                if ((passes & CapturePasses.Labels) != 0)
                    Labels = Create(w, h, CaptureEnvironment.LabelFormat, "NeRF labels" + suffix);
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        static RenderTexture Create(int width, int height, GraphicsFormat format, string name)
        {
            // An explicit GraphicsFormat: the legacy RenderTextureFormat + ReadWrite pair would turn into sRGB or not
            // depending on the project's colour space. 24 depth bits: the passes depth-test the target against itself.
            var descriptor = new RenderTextureDescriptor(width, height, format, 24)
            {
                useMipMap = false,
                autoGenerateMips = false,
                msaaSamples = 1,
            };
            var texture = new RenderTexture(descriptor) { name = name, hideFlags = HideFlags.HideAndDontSave };
            if (!texture.Create())
            {
                Object.DestroyImmediate(texture);
                throw new CaptureException("Unity could not create the " + width + "×" + height + " " + format +
                    " render texture '" + name + "' (out of GPU memory?). Lower the resolution, the supersampling or the readbacks in flight.");
            }
            return texture;
        }

        public void Dispose()
        {
            Destroy(ColorOverBlack);
            Destroy(ColorOverWhite);
            Destroy(Mask);
            Destroy(Depth);
            Destroy(Normal);
            Destroy(Labels);
            ColorOverBlack = ColorOverWhite = Mask = Depth = Normal = Labels = null;
        }

        static void Destroy(RenderTexture texture)
        {
            if (texture == null) return;
            if (RenderTexture.active == texture) RenderTexture.active = null;
            texture.Release();
            Object.DestroyImmediate(texture);
        }
    }
}
