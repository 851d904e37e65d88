namespace NerfDatasetCreator
{
    /// <summary>The pixel layouts the PNG writer accepts; input rows are top row first, tightly packed.</summary>
    public enum PngPixelFormat
    {
        /// <summary>1 byte per pixel (colour type 0, bit depth 8).</summary>
        Gray8,

        /// <summary>3 bytes per pixel, R G B (colour type 2, bit depth 8).</summary>
        Rgb8,

        /// <summary>4 bytes per pixel, R G B A, straight alpha (colour type 6, bit depth 8).</summary>
        Rgba8,

        /// <summary>16-bit gray (colour type 0, bit depth 16): ushort samples, or 2 bytes per pixel big-endian in a byte array.</summary>
        Gray16,
    }
}
