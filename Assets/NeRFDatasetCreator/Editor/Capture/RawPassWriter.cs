using System.Globalization;
using System.IO;
using UnityEngine;
using UnityEngine.Experimental.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A diagnostic <see cref="IViewWriter"/>: writes each view's raw passes as they came off the GPU, before any
    /// dataset post-processing — <c>view_0007_color_over_black.exr</c> and <c>_color_over_white.exr</c> (the two
    /// supersampled colour renders, half float), <c>_mask.png</c>, <c>_depth.exr</c> (32-bit eye depth) and <c>_normal.exr</c> (32-bit normals in the
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
            const Texture2D.EXRFlags exr = Texture2D.EXRFlags.OutputAsFloat | Texture2D.EXRFlags.CompressZIP;
            if (view.ColorOverBlack != null)
            {
                // The two colour renders as the GPU wrote them (half floats; gamma-space values in a Gamma project).
                File.WriteAllBytes(stem + "_color_over_black.exr", ImageConversion.EncodeArrayToEXR(view.ColorOverBlack,
                    GraphicsFormat.R16G16B16A16_SFloat, (uint)view.Width, (uint)view.Height, 0, Texture2D.EXRFlags.CompressZIP));
                File.WriteAllBytes(stem + "_color_over_white.exr", ImageConversion.EncodeArrayToEXR(view.ColorOverWhite,
                    GraphicsFormat.R16G16B16A16_SFloat, (uint)view.Width, (uint)view.Height, 0, Texture2D.EXRFlags.CompressZIP));
            }
            if (view.Mask != null)
            {
                File.WriteAllBytes(stem + "_mask.png", ImageConversion.EncodeArrayToPNG(view.Mask,
                    GraphicsFormat.R8_UNorm, (uint)view.Width, (uint)view.Height));
            }
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
