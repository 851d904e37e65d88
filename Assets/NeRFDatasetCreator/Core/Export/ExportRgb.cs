using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A dataset image for a loader that drops alpha (LLFF's <c>imread(f)[..., :3]</c>, NeuS's <c>cv.imread</c>,
    /// 4DGaussians' <c>ToTensor</c> of an RGB image): 8-bit RGB, the RGBA image composited over the protocol background
    /// (<see cref="ProtocolBackground.For"/>, <see cref="AlphaCompositing.OverSolid"/>); an RGB image is copied as it is.
    /// Without this the loaders would train on the colour stored under transparent pixels.
    /// </summary>
    public static class ExportRgb
    {
        /// <summary>Writes <paramref name="relative"/> (under <paramref name="root"/>) to <paramref name="destination"/> as 8-bit RGB over <paramref name="background"/>.</summary>
        public static void Write(string root, string relative, string destination, (byte R, byte G, byte B) background, StagedOutput staged)
        {
            var source = Path.Combine(root, relative);
            var image = Decode(source, relative);
            if (image.ColorType == PngInfo.ColorTypeRgb)
            {
                staged.Copy(source, destination);
                return;
            }
            staged.WriteNewBytes(destination, PngWriter.Encode(Rgb(image, background), image.Width, image.Height, PngPixelFormat.Rgb8));
        }

        /// <summary>The RGB bytes of an 8-bit RGB or RGBA image over <paramref name="background"/>.</summary>
        public static byte[] Rgb(PngImage image, (byte R, byte G, byte B) background)
        {
            var pixels = image.Width * image.Height;
            var rgb = new byte[pixels * 3];
            if (image.ColorType == PngInfo.ColorTypeRgb) Buffer.BlockCopy(image.Samples, 0, rgb, 0, rgb.Length);
            else AlphaCompositing.OverSolid(image.Samples, rgb, pixels, background.R, background.G, background.B);
            return rgb;
        }

        /// <summary>Decodes an 8-bit RGB or RGBA PNG; anything else is refused, naming the file.</summary>
        public static PngImage Decode(string path, string shown)
        {
            PngImage image;
            try { image = PngReader.Read(path); }
            catch (InvalidDataException e)
            {
                throw Refuse(shown, e.Message);
            }
            if (image.BitDepth != 8 || (image.ColorType != PngInfo.ColorTypeRgb && image.ColorType != PngInfo.ColorTypeRgba))
                throw Refuse(shown, "is not an 8-bit RGB or RGBA PNG (colour type " + image.ColorType + ", " + image.BitDepth + " bits).");
            return image;
        }

        static InvalidParameterException Refuse(string file, string reason) =>
            new InvalidParameterException(new[] { new ValidationProblem("file_path", file, reason, "Re-capture the dataset with this plugin (8-bit PNG colour images).") });
    }
}
