namespace NerfDatasetCreator
{
    /// <summary>
    /// The view stage of <c>r_&lt;i&gt;_hdr.exr</c>: the colour of the difference-matting pair (<see cref="DifferenceMatting"/>)
    /// in linear light, k×k box-filtered, with straight alpha, and without the two steps that make the PNG: no clip to
    /// [0, 1] and no sRGB encoding. Per sample, T = W − K, alpha a = clamp(1 − mean(T), 0, 1), premultiplied colour
    /// (2K + T − (1 − a)) / 2 — the matting's least-squares solve —; per pixel, straight colour = Σ premultiplied / Σ a
    /// (un-premultiplied in float; negative values, which only rounding of an empty sample makes, become 0), alpha = Σ a / k².
    /// Over a solid background each sample is K + T·B and alpha is 1, as in the PNG. So sRGB(min(1, colour)) is the PNG's
    /// colour and round(255·alpha) its alpha, up to float rounding (<see cref="HdrCheck"/> holds the two to that).
    /// A Gamma colour-space project renders gamma-space values, which are not linear light: refused.
    /// </summary>
    public static class HdrColour
    {
        /// <summary>OutputWidth × OutputHeight × 4 floats (R G B A), rows bottom-up (texture order, as <see cref="ExrEncoder"/> takes them).</summary>
        public static float[] Resolve(RawFrame frame, Background background = default)
        {
            var problems = frame.Validate();
            if (frame.ColorOverBlack == null)
                problems.Add(new ValidationProblem("frame.ColorOverBlack", "null", "is required: the HDR image is solved from the colour pass over black and over white.",
                    "Read back both colour renders into frame.ColorOverBlack and frame.ColorOverWhite."));
            if (frame.ColorIsGammaEncoded)
                problems.Add(new ValidationProblem("hdr", "Gamma colour space", "renders gamma-space values, not linear light, so there is no HDR colour to write.",
                    "Set Project Settings ▸ Player ▸ Color Space to Linear, or remove the \"hdr\" section."));
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            int k = frame.Supersampling, width = frame.Width, ow = frame.OutputWidth, oh = frame.OutputHeight;
            float[] half = HalfFloat.Lookup;
            ushort[] black = frame.ColorOverBlack, white = frame.ColorOverWhite;
            float samples = k * k;
            var output = new float[ow * oh * 4];
            for (int oy = 0, o = 0; oy < oh; oy++)
                for (int ox = 0; ox < ow; ox++, o += 4)
                {
                    float alphaSum = 0, r = 0, g = 0, b = 0;
                    for (int dy = 0; dy < k; dy++)
                    {
                        int c = ((oy * k + dy) * width + ox * k) * 4;
                        for (int dx = 0; dx < k; dx++, c += 4)
                        {
                            float kr = half[black[c]], kg = half[black[c + 1]], kb = half[black[c + 2]];
                            float tr = half[white[c]] - kr, tg = half[white[c + 1]] - kg, tb = half[white[c + 2]] - kb;
                            if (background.IsSolid)
                            {
                                r += kr + tr * background.LinearR;
                                g += kg + tg * background.LinearG;
                                b += kb + tb * background.LinearB;
                                continue;
                            }
                            float a = 1f - (tr + tg + tb) * (1f / 3f);
                            if (a > 1) a = 1;
                            if (!(a > 0)) continue; // nothing covers this sample
                            float t = 1f - a;
                            alphaSum += a;
                            r += (kr + kr + tr - t) * 0.5f;
                            g += (kg + kg + tg - t) * 0.5f;
                            b += (kb + kb + tb - t) * 0.5f;
                        }
                    }
                    if (background.IsSolid)
                    {
                        output[o] = Positive(r / samples);
                        output[o + 1] = Positive(g / samples);
                        output[o + 2] = Positive(b / samples);
                        output[o + 3] = 1;
                        continue;
                    }
                    if (!(alphaSum > 0)) continue; // (0, 0, 0, 0)
                    output[o] = Positive(r / alphaSum);
                    output[o + 1] = Positive(g / alphaSum);
                    output[o + 2] = Positive(b / alphaSum);
                    output[o + 3] = alphaSum / samples;
                }
            return output;
        }

        static float Positive(float v) => v > 0 ? v : 0;
    }
}
