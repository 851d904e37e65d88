namespace NerfDatasetCreator
{
    /// <summary>
    /// Straight-alpha RGBA composited over a solid colour on the stored 8-bit sRGB values, as the Blender loaders do
    /// (<c>rgb·a + bg·(1 − a)</c> on values in [0, 1]: graphdeco 3DGS <c>readCamerasFromTransforms</c>, nerf-pytorch
    /// <c>load_blender</c> with <c>--white_bkgd</c>, nerfstudio's <c>alpha_color</c>), rounded to the nearest code:
    /// <c>out = ⌊(c·a + bg·(255 − a) + 127) / 255⌋</c> in integers, so the result is exact and the same on every runtime.
    /// (3DGS keeps its composite in float32 and truncates when it makes a PIL image, which can be one code lower.)
    /// </summary>
    public static class AlphaCompositing
    {
        /// <summary>One channel: <paramref name="colour"/> at coverage <paramref name="alpha"/> over <paramref name="background"/>.</summary>
        public static byte Over(byte colour, byte alpha, byte background) =>
            (byte)((colour * alpha + background * (255 - alpha) + 127) / 255);

        /// <summary>
        /// Writes <paramref name="pixels"/> RGB triples into <paramref name="rgb"/> from the RGBA quadruples in
        /// <paramref name="rgba"/>, each over (<paramref name="r"/>, <paramref name="g"/>, <paramref name="b"/>).
        /// </summary>
        public static void OverSolid(byte[] rgba, byte[] rgb, int pixels, byte r, byte g, byte b)
        {
            if (rgba == null || rgba.Length < (long)pixels * 4) throw new System.ArgumentException("rgba holds fewer than 4 bytes per pixel.", nameof(rgba));
            if (rgb == null || rgb.Length < (long)pixels * 3) throw new System.ArgumentException("rgb holds fewer than 3 bytes per pixel.", nameof(rgb));
            for (int i = 0, s = 0, d = 0; i < pixels; i++, s += 4, d += 3)
            {
                var a = rgba[s + 3];
                rgb[d] = Over(rgba[s], a, r);
                rgb[d + 1] = Over(rgba[s + 1], a, g);
                rgb[d + 2] = Over(rgba[s + 2], a, b);
            }
        }
    }
}
