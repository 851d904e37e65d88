using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What a missing PNG is, when another image is there instead (issue 33: a JPEG dataset read as
    /// "r_0.jpg.png is missing"): bmild/nerf, nerf-pytorch, nerfstudio's blender-data and 3DGS's Blender reader append
    /// ".png" to <c>file_path</c>, and this tool decodes PNG only, so a dataset of JPEGs needs its images converted.
    /// </summary>
    public static class ImageFormats
    {
        /// <summary>The problem for a frame whose PNG <paramref name="pngPath"/> (shown as <paramref name="shown"/>) is missing: a JPEG beside it is named.</summary>
        public static string MissingPng(string shown, string pngPath)
        {
            foreach (var extension in new[] { ".jpg", ".jpeg", ".JPG", ".JPEG" })
            {
                var other = Path.ChangeExtension(pngPath, extension);
                if (File.Exists(other))
                    return "image " + shown + " is missing, but " + Path.ChangeExtension(shown, extension) + " is there (" + Describe(other) + "): the loaders and this tool read PNG. " + ConvertAdvice;
            }
            return "image " + shown + " is missing.";
        }

        /// <summary>The problem for an image that is a JPEG (file_path "./train/r_0.jpg"), instead of "is not a PNG file".</summary>
        public static string NotPng(string shown) =>
            shown + " is a JPEG; bmild/nerf, nerf-pytorch, nerfstudio's blender-data and 3DGS read PNG (they append \".png\" to file_path), and so does this tool. " + ConvertAdvice;

        const string ConvertAdvice = "Convert the images to PNG (e.g. `mogrify -format png */*.jpg`) and write file_path without an extension (./train/r_0).";

        /// <summary>"a JPEG" by its first bytes (FF D8 FF), else "a .xyz file".</summary>
        public static string Describe(string path) => IsJpeg(path) ? "a JPEG" : "a " + Path.GetExtension(path) + " file";

        public static bool IsJpeg(string path)
        {
            try
            {
                // Through the one gate for every file read: a pipe or device named like a JPEG is never opened.
                using (var stream = ReadableFile.OpenRead(path, long.MaxValue))
                {
                    var head = new byte[3];
                    return stream.Read(head, 0, 3) == 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF;
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return false;
            }
        }
    }
}
