using System.Globalization;
using System.IO;
using UnityEngine;
using UnityEngine.Experimental.Rendering;

namespace NerfDatasetCreator.Editor.Capture
{
    /// <summary>
    /// A diagnostic <see cref="IViewWriter"/>: writes each view's raw passes as they came off the GPU, before any
    /// dataset post-processing — <c>view_0007_color.png</c> (supersampled, colour bytes with the mask as alpha, so
    /// edges are premultiplied), <c>_depth.exr</c> (32-bit eye depth) and <c>_normal.exr</c> (32-bit normals in the
    /// output world frame, alpha = coverage). For checking passes in a real Editor, not a dataset. Encodes with
    /// Unity's thread-safe <c>ImageConversion.EncodeArrayToPNG/EXR</c> on the worker thread.
    /// </summary>
    public sealed class RawPassWriter : IViewWriter
    {
        readonly string _folder;

        public RawPassWriter(string folder)
        {
            _folder = folder;
            Directory.CreateDirectory(folder);
        }

        public void Write(CapturedView view)
        {
            var stem = Path.Combine(_folder, "view_" + view.ViewIndex.ToString("0000", CultureInfo.InvariantCulture));
            if (view.Color != null)
            {
                var rgba = new byte[view.Color.Length];
                for (var i = 0; i < view.Width * view.Height; i++)
                {
                    rgba[i * 4] = view.Color[i * 4];
                    rgba[i * 4 + 1] = view.Color[i * 4 + 1];
                    rgba[i * 4 + 2] = view.Color[i * 4 + 2];
                    rgba[i * 4 + 3] = view.Mask == null ? (byte)255 : view.Mask[i];
                }
                // UNorm, not _SRGB: the bytes are already sRGB-encoded and must be stored as they are.
                File.WriteAllBytes(stem + "_color.png", ImageConversion.EncodeArrayToPNG(rgba,
                    GraphicsFormat.R8G8B8A8_UNorm, (uint)view.Width, (uint)view.Height));
            }
            else if (view.Mask != null)
            {
                File.WriteAllBytes(stem + "_mask.png", ImageConversion.EncodeArrayToPNG(view.Mask,
                    GraphicsFormat.R8_UNorm, (uint)view.Width, (uint)view.Height));
            }
            const Texture2D.EXRFlags exr = Texture2D.EXRFlags.OutputAsFloat | Texture2D.EXRFlags.CompressZIP;
            if (view.Depth != null)
                File.WriteAllBytes(stem + "_depth.exr", ImageConversion.EncodeArrayToEXR(view.Depth,
                    GraphicsFormat.R32_SFloat, (uint)view.DataWidth, (uint)view.DataHeight, 0, exr));
            if (view.Normal != null)
            {
                NormalFrames.ToOutputWorld(view.Normal);
                File.WriteAllBytes(stem + "_normal.exr", ImageConversion.EncodeArrayToEXR(view.Normal,
                    GraphicsFormat.R32G32B32A32_SFloat, (uint)view.DataWidth, (uint)view.DataHeight, 0, exr));
            }
        }
    }
}
