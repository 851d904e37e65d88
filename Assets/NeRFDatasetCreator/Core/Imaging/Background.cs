namespace NerfDatasetCreator
{
    /// <summary>
    /// What the colour image shows where the target does not cover a pixel: nothing (straight-alpha RGBA, the
    /// nerf_synthetic default) or a solid colour composited in linear light, which makes every alpha 255.
    /// </summary>
    public readonly struct Background
    {
        Background(bool isSolid, float r, float g, float b)
        {
            IsSolid = isSolid;
            LinearR = r;
            LinearG = g;
            LinearB = b;
        }

        public bool IsSolid { get; }
        public float LinearR { get; }
        public float LinearG { get; }
        public float LinearB { get; }

        public static Background Transparent => default;

        /// <summary>A solid colour given as sRGB bytes, e.g. 255,255,255 for white (what a colour picker shows).</summary>
        public static Background SolidSrgb(byte r, byte g, byte b) => new Background(true, Srgb.Decode(r), Srgb.Decode(g), Srgb.Decode(b));

        /// <summary>A solid colour in linear light (Unity's <c>Color.linear</c>); each channel is clamped to [0, 1].</summary>
        public static Background SolidLinear(double r, double g, double b) => new Background(true, Clamp(r), Clamp(g), Clamp(b));

        static float Clamp(double v) => v > 1 ? 1f : v > 0 ? (float)v : 0f;
    }
}
