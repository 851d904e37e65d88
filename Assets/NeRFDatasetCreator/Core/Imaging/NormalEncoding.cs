namespace NerfDatasetCreator
{
    /// <summary>
    /// The normal image: 8-bit RGB, top row first, each channel round((n·0.5 + 0.5)·255) of a unit normal given in
    /// the dataset's frame (the rotation into it happens before, in the capture layer). Negative components keep
    /// their full range (−1 → 0, 0 → 128, +1 → 255); background is (0,0,0), which no unit vector encodes to.
    /// Point-sampled by the <see cref="PointSampling"/> rule, never averaged.
    /// </summary>
    public static class NormalEncoding
    {
        /// <summary>Writes OutputWidth×OutputHeight×3 bytes (R G B) into <paramref name="rgb"/>.</summary>
        public static void Encode(RawFrame frame, byte[] rgb)
        {
            frame.Require(color: false, mask: false, depth: false, normals: true);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("rgb", rgb, (long)ow * oh * 3, "bytes (3 per output pixel)");

            int stride = frame.NormalFloatsPerPixel;
            float[] normals = frame.Normals;
            // Offsets of the output's y and z in a source pixel: swapped for Unity world normals.
            int yAt = frame.NormalsInUnityWorld ? 2 : 1, zAt = 3 - yAt;
            if (frame.Supersampling == 1)
            {
                EncodeOneSamplePerPixel(frame, rgb);
                return;
            }
            int[] order = PointSampling.Order(frame.Supersampling, frame.Width);

            for (int oy = 0; oy < oh; oy++)
            {
                int o = oy * ow * 3;
                for (int ox = 0; ox < ow; ox++, o += 3)
                {
                    int hit = Hit(frame, order, ox, oy);
                    if (hit < 0)
                    {
                        rgb[o] = 0;
                        rgb[o + 1] = 0;
                        rgb[o + 2] = 0;
                        continue;
                    }
                    rgb[o] = Component(normals[hit]);
                    rgb[o + 1] = Component(normals[hit + yAt]);
                    rgb[o + 2] = Component(normals[hit + zAt]);
                }
            }
        }

        /// <summary>
        /// Supersampling 1 — the capture renders its data passes at the output size — so each pixel is its own
        /// sample: one flat loop with <see cref="Component"/> written out, because Mono does not inline it.
        /// </summary>
        static void EncodeOneSamplePerPixel(RawFrame frame, byte[] rgb)
        {
            // Read here rather than passed in: with fewer parameters Mono keeps the loop's indices in registers.
            float[] normals = frame.Normals;
            int ow = frame.OutputWidth, oh = frame.OutputHeight, stride = frame.NormalFloatsPerPixel;
            int yAt = frame.NormalsInUnityWorld ? 2 : 1, zAt = 3 - yAt;
            for (int oy = 0; oy < oh; oy++)
            {
                int n = (oh - 1 - oy) * ow * stride; // source rows are bottom-up
                int o = oy * ow * 3;
                for (int ox = 0; ox < ow; ox++, n += stride, o += 3)
                {
                    float x = normals[n], y = normals[n + yAt], z = normals[n + zAt];
                    float lengthSquared = x * x + y * y + z * z;
                    if (!(lengthSquared > 0.25f))
                    {
                        rgb[o] = 0;
                        rgb[o + 1] = 0;
                        rgb[o + 2] = 0;
                        continue;
                    }
                    if (lengthSquared < 4f)
                    {
                        // Every component is in (−2, 2), so v·127.5 + 128 is in (−127, 383): truncated to an int and
                        // clamped to [0, 255] in integers it is Component(v) exactly (v ≤ −1 gives at most 0.5 → 0,
                        // v ≥ 1 at least 255.5 → 255). Integer tests rather than two float tests per component: Mono
                        // keeps floats on the stack and pays for each float comparison and conditional.
                        int c = (int)(x * 127.5f + 128f);
                        if (c < 0) c = 0;
                        else if (c > 255) c = 255;
                        rgb[o] = (byte)c;
                        c = (int)(y * 127.5f + 128f);
                        if (c < 0) c = 0;
                        else if (c > 255) c = 255;
                        rgb[o + 1] = (byte)c;
                        c = (int)(z * 127.5f + 128f);
                        if (c < 0) c = 0;
                        else if (c > 255) c = 255;
                        rgb[o + 2] = (byte)c;
                        continue;
                    }
                    rgb[o] = !(x > -1) ? (byte)0 : x >= 1 ? (byte)255 : (byte)(int)(x * 127.5f + 128f);
                    rgb[o + 1] = !(y > -1) ? (byte)0 : y >= 1 ? (byte)255 : (byte)(int)(y * 127.5f + 128f);
                    rgb[o + 2] = !(z > -1) ? (byte)0 : z >= 1 ? (byte)255 : (byte)(int)(z * 127.5f + 128f);
                }
            }
        }

        /// <summary>
        /// The float image for an EXR: 4 floats per output pixel (x, y, z, 1) of the point-sampled unit normal, or
        /// (0, 0, 0, 0) where there is no surface, in <paramref name="rows"/> order — Unity's
        /// ImageConversion.EncodeArrayToEXR takes texture order, <see cref="RowDirection.BottomRowFirst"/>.
        /// </summary>
        public static void ToFloats(RawFrame frame, float[] rgba, RowDirection rows)
        {
            frame.Require(color: false, mask: false, depth: false, normals: true);
            int ow = frame.OutputWidth, oh = frame.OutputHeight;
            RawFrame.RequireOutput("rgba", rgba, (long)ow * oh * 4, "floats (4 per output pixel)");

            float[] normals = frame.Normals;
            int yAt = frame.NormalsInUnityWorld ? 2 : 1, zAt = 3 - yAt;
            int[] order = PointSampling.Order(frame.Supersampling, frame.Width);
            for (int oy = 0; oy < oh; oy++)
            {
                int o = (rows == RowDirection.TopRowFirst ? oy : oh - 1 - oy) * ow * 4;
                for (int ox = 0; ox < ow; ox++, o += 4)
                {
                    int hit = Hit(frame, order, ox, oy);
                    rgba[o] = hit < 0 ? 0 : normals[hit];
                    rgba[o + 1] = hit < 0 ? 0 : normals[hit + yAt];
                    rgba[o + 2] = hit < 0 ? 0 : normals[hit + zAt];
                    rgba[o + 3] = hit < 0 ? 0 : 1;
                }
            }
        }

        /// <summary>
        /// Offset in <see cref="RawFrame.Normals"/> of the sample output pixel (ox, oy) — counted from the top row —
        /// takes: the first of its block's samples in <see cref="PointSampling"/> order that hit a surface; −1 for none.
        /// </summary>
        static int Hit(RawFrame frame, int[] order, int ox, int oy)
        {
            int k = frame.Supersampling, stride = frame.NormalFloatsPerPixel;
            float[] normals = frame.Normals;
            int first = RowOrder.SourceBlockRow(oy, frame.OutputHeight, k) * frame.Width + ox * k;
            for (int i = 0; i < order.Length; i++)
            {
                int n = (first + order[i]) * stride;
                float x = normals[n], y = normals[n + 1], z = normals[n + 2];
                // The clear is (0,0,0); a real normal has length ≈ 1. NaN fails the test and counts as background.
                if (x * x + y * y + z * z > 0.25f) return n;
            }
            return -1;
        }

        /// <summary>round((v·0.5 + 0.5)·255) with halves up, v clamped to [−1, 1]: floor(v·127.5 + 128).</summary>
        public static byte Component(float v)
        {
            if (!(v > -1)) return 0;
            if (v >= 1) return 255;
            return (byte)(v * 127.5f + 128f);
        }
    }
}
