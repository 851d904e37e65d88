namespace NerfDatasetCreator
{
    /// <summary>
    /// The files of a material pass from its straight per-pixel values (<see cref="MaterialPassResolve"/>, top row first):
    /// the float32 RGBA EXR as they are, and the 8-bit RGBA PNG in the pass's encoding — sRGB for colours (base colour,
    /// specular), no curve for scalars (metallic, roughness) — with the colour image's alpha byte. The reasons for each
    /// encoding are in Documentation~/maintainers/materials.md.
    /// </summary>
    public static class MaterialEncoding
    {
        /// <summary>round(255·sRGB(v)) for v clamped to [0, 1]: 0.5 → 188.</summary>
        public static byte SrgbByte(float linear) => Srgb.Encode(linear);

        /// <summary>round(255·v) for v clamped to [0, 1], no curve: 0.5 → 128.</summary>
        public static byte LinearByte(float value)
        {
            if (!(value > 0)) return 0;
            if (value >= 1) return 255;
            return (byte)(value * 255f + 0.5f);
        }

        /// <summary>The PNG's RGBA bytes, top row first: RGB encoded as <paramref name="encoding"/> says, A = <paramref name="alpha"/>.</summary>
        public static byte[] PngBytes(float[] straight, byte[] alpha, MaterialPngEncoding encoding) => PngBytes(straight, alpha, encoding, new byte[alpha.Length * 4]);

        /// <summary><see cref="PngBytes(float[], byte[], MaterialPngEncoding)"/> into <paramref name="rgba"/>, which it returns.</summary>
        public static byte[] PngBytes(float[] straight, byte[] alpha, MaterialPngEncoding encoding, byte[] rgba)
        {
            var n = alpha.Length;
            for (int i = 0, o = 0; i < n; i++, o += 4)
            {
                for (var c = 0; c < 3; c++)
                    rgba[o + c] = encoding == MaterialPngEncoding.Srgb ? SrgbByte(straight[o + c]) : LinearByte(straight[o + c]);
                rgba[o + 3] = alpha[i];
            }
            return rgba;
        }

        /// <summary>The values bottom row first, as <see cref="ExrEncoder"/> takes them (texture order).</summary>
        public static float[] ExrOrder(float[] straight, int width, int height) => ExrOrder(straight, width, height, new float[straight.Length]);

        /// <summary><see cref="ExrOrder(float[], int, int)"/> into <paramref name="flipped"/>, which it returns.</summary>
        public static float[] ExrOrder(float[] straight, int width, int height, float[] flipped)
        {
            RowOrder.FlipRows(straight, flipped, width * 4, height);
            return flipped;
        }
    }
}
