using UnityEditor;
using UnityEngine;
using UnityEngine.Experimental.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Core's JPEG codec in the Editor (<see cref="IJpegCodec"/>): Unity's own encoder, so the package ships no JPEG
    /// binary. Installed whenever the Editor loads this assembly (<c>[InitializeOnLoadMethod]</c>, UnityCsReference
    /// 2022.3.76f1 Editor/Mono/EditorAssemblies.cs:36, run by ProcessInitializeOnLoadMethodAttributes :138; the same in
    /// 6000.0.78f1). Encoding is <c>ImageConversion.EncodeArrayToJPG</c>, bound as a thread-safe free function
    /// (<c>[FreeFunctionAttribute("ImageConversionBindings::EncodeArrayToJPG", true)]</c>,
    /// Modules/ImageConversion/ScriptBindings/ImageConversion.bindings.cs:68–69 in 2022.3.76f1, :71–72 in 6000.0.78f1),
    /// so convert may call it from a worker. Its rows are in texture order (bottom row first), so they are flipped.
    /// Decoding (checks and tests only) goes through <c>Texture2D.LoadImage</c> (:56–59), main thread only.
    /// Unity does not document its JPEG chroma subsampling: the PSNR of its files is measured by a Test Runner test
    /// (UnityJpegCodecTests), not assumed equal to the tool's 4:4:4 figure.
    /// </summary>
    sealed class UnityJpegCodec : IJpegCodec
    {
        [InitializeOnLoadMethod]
        static void Install()
        {
            if (JpegWriter.Codec == null) JpegWriter.Codec = new UnityJpegCodec();
        }

        public string Name => "Unity ImageConversion.EncodeArrayToJPG";

        public byte[] Encode(byte[] rgb, int width, int height, int quality) =>
            ImageConversion.EncodeArrayToJPG(FlipRows(rgb, width, height, 3), GraphicsFormat.R8G8B8_SRGB, (uint)width, (uint)height, 0, quality);

        public byte[] Decode(byte[] jpeg, out int width, out int height)
        {
            var texture = new Texture2D(2, 2, TextureFormat.RGB24, false);
            try
            {
                if (!texture.LoadImage(jpeg)) throw new System.IO.InvalidDataException("Unity could not decode the JPEG.");
                width = texture.width;
                height = texture.height;
                // Texture2D.GetPixels32 (docs: ScriptReference/Texture2D.GetPixels32): "a flattened 2D array, where pixels are
                // laid out left to right, bottom to top", so row y of the image is row height − 1 − y here.
                var pixels = texture.GetPixels32();
                var rgb = new byte[width * height * 3];
                for (var y = 0; y < height; y++)
                    for (var x = 0; x < width; x++)
                    {
                        var p = pixels[(height - 1 - y) * width + x];
                        var i = 3 * (y * width + x);
                        rgb[i] = p.r;
                        rgb[i + 1] = p.g;
                        rgb[i + 2] = p.b;
                    }
                return rgb;
            }
            finally
            {
                Object.DestroyImmediate(texture);
            }
        }

        static byte[] FlipRows(byte[] pixels, int width, int height, int channels)
        {
            var row = width * channels;
            var flipped = new byte[pixels.Length];
            for (var y = 0; y < height; y++) System.Buffer.BlockCopy(pixels, y * row, flipped, (height - 1 - y) * row, row);
            return flipped;
        }
    }
}
