using System;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The fallback where <c>SystemInfo.supportsAsyncGPUReadback</c> is false: <c>Texture2D.ReadPixels</c> from each
    /// render texture into a reused CPU texture of the same GraphicsFormat (no conversion), then its raw data.
    /// </summary>
    sealed class SynchronousReadback : IDisposable
    {
        Texture2D _black, _white, _mask, _depth, _normal, _labels;

        public void ReadInto(RenderTargetSet targets, CapturedView view, CapturePools pools)
        {
            var previous = RenderTexture.active;
            try
            {
                if (targets.ColorOverBlack != null)
                {
                    view.ColorOverBlack = ViewReadback.CopyExact(Read(targets.ColorOverBlack, ref _black).GetRawTextureData<ushort>(), pools.Color, "colour (over black)");
                    view.ColorOverWhite = ViewReadback.CopyExact(Read(targets.ColorOverWhite, ref _white).GetRawTextureData<ushort>(), pools.Color, "colour (over white)");
                }
                if (targets.Mask != null)
                {
                    var raw = Read(targets.Mask, ref _mask).GetRawTextureData<byte>();
                    view.Mask = targets.Mask.graphicsFormat == GraphicsFormat.R8_UNorm
                        ? ViewReadback.CopyExact(raw, pools.Mask, "mask")
                        : ViewReadback.RedChannel(raw, pools.Mask);
                }
                if (targets.Depth != null) view.Depth = ViewReadback.CopyExact(Read(targets.Depth, ref _depth).GetRawTextureData<float>(), pools.Depth, "depth");
                if (targets.Normal != null) view.Normal = ViewReadback.CopyExact(Read(targets.Normal, ref _normal).GetRawTextureData<float>(), pools.Normal, "normal");
                if (targets.Labels != null) view.Labels = ViewReadback.CopyExact(Read(targets.Labels, ref _labels).GetRawTextureData<byte>(), pools.Labels, "labels");
            }
            finally
            {
                RenderTexture.active = previous;
            }
        }

        /// <summary>Motion blur's sub-frames: the colour pair only, into the given arrays.</summary>
        public void ReadColour(RenderTargetSet targets, ushort[] overBlack, ushort[] overWhite)
        {
            var previous = RenderTexture.active;
            try
            {
                Read(targets.ColorOverBlack, ref _black).GetRawTextureData<ushort>().CopyTo(overBlack);
                Read(targets.ColorOverWhite, ref _white).GetRawTextureData<ushort>().CopyTo(overWhite);
            }
            finally
            {
                RenderTexture.active = previous;
            }
        }

        static Texture2D Read(RenderTexture source, ref Texture2D cpu)
        {
            if (cpu == null)
            {
                if (!CaptureEnvironment.CanReadPixels(source.graphicsFormat))
                    throw new CaptureException("This GPU supports neither asynchronous readback nor ReadPixels of " +
                        source.graphicsFormat + " (" + source.name + "). Turn that pass off or capture on another machine.");
                cpu = new Texture2D(source.width, source.height, source.graphicsFormat, TextureCreationFlags.None)
                {
                    name = source.name + " readback",
                    hideFlags = HideFlags.HideAndDontSave,
                };
            }
            RenderTexture.active = source;
            // recalculateMipMaps false: the texture has no mips; Apply() is not needed, only the CPU copy is read.
            cpu.ReadPixels(new Rect(0, 0, source.width, source.height), 0, 0, false);
            return cpu;
        }

        public void Dispose()
        {
            foreach (var texture in new[] { _black, _white, _mask, _depth, _normal, _labels })
                if (texture != null) Object.DestroyImmediate(texture);
            _black = _white = _mask = _depth = _normal = _labels = null;
        }
    }
}
