namespace NerfDatasetCreator
{
    /// <summary>Which files an extra pass (depth, normal) writes per view.</summary>
    public enum ExtraOutput
    {
        None,
        /// <summary>The loader-facing PNG (16-bit millimetres for depth, 8-bit n·0.5+0.5 for normals).</summary>
        Png,
        /// <summary>Float32 OpenEXR only (depth in metres, normals as unit vectors).</summary>
        Exr,
        PngAndExr,
    }

    public static class ExtraOutputs
    {
        public static bool HasPng(ExtraOutput output) => output == ExtraOutput.Png || output == ExtraOutput.PngAndExr;
        public static bool HasExr(ExtraOutput output) => output == ExtraOutput.Exr || output == ExtraOutput.PngAndExr;

        public static string Name(ExtraOutput output)
        {
            switch (output)
            {
                case ExtraOutput.Png: return "png";
                case ExtraOutput.Exr: return "exr";
                case ExtraOutput.PngAndExr: return "png+exr";
                default: return "none";
            }
        }

        public static bool TryParse(string name, out ExtraOutput output)
        {
            foreach (var candidate in new[] { ExtraOutput.None, ExtraOutput.Png, ExtraOutput.Exr, ExtraOutput.PngAndExr })
                if (string.Equals(Name(candidate), name, System.StringComparison.OrdinalIgnoreCase))
                {
                    output = candidate;
                    return true;
                }
            output = ExtraOutput.None;
            return false;
        }
    }
}
