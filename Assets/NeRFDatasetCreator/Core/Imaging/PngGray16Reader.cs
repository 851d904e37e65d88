using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The samples of a 16-bit greyscale PNG — the depth files this plugin writes — for the exporters that re-encode
    /// depth. Decoding is <see cref="PngReader"/>'s; every other kind of PNG is refused with a problem naming the file.
    /// </summary>
    public static class PngGray16Reader
    {
        /// <summary>The samples, top row first.</summary>
        public static ushort[] Read(string path, out int width, out int height)
        {
            PngImage image;
            try
            {
                image = PngReader.Read(path);
            }
            catch (InvalidDataException e)
            {
                throw Bad(path, e.Message.StartsWith(path) ? e.Message.Substring(path.Length).TrimStart() : e.Message);
            }
            if (image.BitDepth != 16 || image.ColorType != PngInfo.ColorTypeGray)
                throw Bad(path, "is not a 16-bit greyscale, non-interlaced PNG (the depth layout).");
            width = image.Width;
            height = image.Height;
            var samples = new ushort[width * height];
            var bytes = image.Samples;
            for (var i = 0; i < samples.Length; i++) samples[i] = (ushort)((bytes[2 * i] << 8) | bytes[2 * i + 1]);
            return samples;
        }

        static InvalidParameterException Bad(string path, string reason) =>
            new InvalidParameterException(new[] { new ValidationProblem("depth", path, reason, "Re-capture the depth with this plugin (16-bit PNG).") });
    }
}
