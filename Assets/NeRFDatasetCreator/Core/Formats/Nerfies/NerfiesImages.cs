using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The images of the Nerfies-family layouts, <c>rgb/&lt;k&gt;x/&lt;id&gt;.png</c>. The readers drop alpha:
    /// Nerfies and HyperNeRF decode with <c>cv2.IMREAD_COLOR</c> (nerfies/datasets/nerfies.py:57–63, hypernerf's
    /// line 64) and 4DGaussians keeps <c>[:3]</c> (hyper_loader.py:159), so the RGB is composited over the dataset's
    /// protocol background (<see cref="ProtocolBackground"/>, <see cref="AlphaCompositing"/>). DyCheck reads RGBA and takes
    /// alpha as "valid pixel" (datasets/nerfies.py:561–562 rgb, mask; iPhone's val images are alpha 255, iphone.py:473–476):
    /// every pixel of a render is valid, so alpha is 255 everywhere.
    /// Level k (1, 2, 4, 8) is the k × k box mean of the composited 1x codes, rounded half up — compositing is linear
    /// in premultiplied colour, so this is the premultiplied box filter of the RGBA image, composited; a level is written
    /// only when k divides both sides (the readers' scaled camera, camera.py:323–340, then matches the pixels exactly).
    /// </summary>
    public static class NerfiesImages
    {
        public static readonly int[] Levels = { 1, 2, 4, 8 };

        /// <summary>The 1x RGB of the frame's image over (<paramref name="r"/>, <paramref name="g"/>, <paramref name="b"/>): 3 bytes a pixel.</summary>
        public static byte[] Composited(ExportScene scene, ExportFrame frame, byte r, byte g, byte b)
        {
            var image = ExportRgb.Decode(Path.Combine(scene.RootDirectory, frame.ImagePath), frame.ImagePath);
            var k = scene.Intrinsics;
            if (image.Width != k.Width || image.Height != k.Height)
                throw NerfiesViews.Refuse("file_path", frame.ImagePath, "is " + image.Width + " × " + image.Height + ", not the dataset's " + k.Width + " × " + k.Height + ".",
                    "Re-capture the dataset: every image has the camera's size.");
            return ExportRgb.Rgb(image, (r, g, b));
        }

        /// <summary>Whether level <paramref name="factor"/> is written for a <paramref name="width"/> × <paramref name="height"/> image.</summary>
        public static bool Fits(int factor, int width, int height) => width % factor == 0 && height % factor == 0;

        /// <summary>The <paramref name="factor"/> × <paramref name="factor"/> box mean of 3-channel <paramref name="rgb"/>, each channel ⌊(sum + n/2) / n⌋ for n = factor².</summary>
        public static byte[] Downscale(byte[] rgb, int width, int height, int factor)
        {
            if (!Fits(factor, width, height)) throw new ArgumentException(factor + " does not divide " + width + " × " + height + ".", nameof(factor));
            if (factor == 1) return rgb;
            int w = width / factor, h = height / factor, n = factor * factor;
            var result = new byte[w * h * 3];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                    for (var c = 0; c < 3; c++)
                    {
                        var sum = 0;
                        for (var dy = 0; dy < factor; dy++)
                            for (var dx = 0; dx < factor; dx++)
                                sum += rgb[((y * factor + dy) * width + x * factor + dx) * 3 + c];
                        result[(y * w + x) * 3 + c] = (byte)((sum + n / 2) / n);
                    }
            return result;
        }

        /// <summary>RGB with alpha 255 on every pixel (DyCheck: every rendered pixel is valid).</summary>
        public static byte[] Opaque(byte[] rgb)
        {
            var pixels = rgb.Length / 3;
            var rgba = new byte[pixels * 4];
            for (var i = 0; i < pixels; i++)
            {
                rgba[4 * i] = rgb[3 * i];
                rgba[4 * i + 1] = rgb[3 * i + 1];
                rgba[4 * i + 2] = rgb[3 * i + 2];
                rgba[4 * i + 3] = 255;
            }
            return rgba;
        }
    }
}
