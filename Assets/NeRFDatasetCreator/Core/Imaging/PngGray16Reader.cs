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
        /// <param name="what">What the file is, for the messages: "depth" (the default) or "instance map" — an 8-bit instance map is not a depth problem.</param>
        public static ushort[] Read(string path, out int width, out int height, string what = "depth")
        {
            PngImage image;
            try
            {
                image = PngReader.Read(path);
            }
            catch (InvalidDataException e)
            {
                throw Bad(path, e.Message.StartsWith(path) ? e.Message.Substring(path.Length).TrimStart() : e.Message, what);
            }
            if (image.BitDepth != 16 || image.ColorType != PngInfo.ColorTypeGray)
                throw Bad(path, "is not a 16-bit greyscale, non-interlaced PNG (the " + what + " layout).", what);
            width = image.Width;
            height = image.Height;
            var samples = new ushort[width * height];
            var bytes = image.Samples;
            for (var i = 0; i < samples.Length; i++) samples[i] = (ushort)((bytes[2 * i] << 8) | bytes[2 * i + 1]);
            return samples;
        }

        static InvalidParameterException Bad(string path, string reason, string what) =>
            new InvalidParameterException(new[] { new ValidationProblem(what, path, reason, "Re-capture the " + what + " with this plugin (16-bit PNG).") });
    }
}
