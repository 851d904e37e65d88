namespace NerfDatasetCreator
{
    /// <summary>
    /// The view stage of the material passes: from the supersampled readback (<see cref="RawFrame.MaterialAlbedo"/> …,
    /// rows bottom-up) to straight per-pixel values, top row first. Each output pixel is the k×k box average of its samples
    /// weighted by coverage — the mask pass's coverage times <see cref="RawFrame.MaterialSupported"/> — so an edge pixel holds
    /// the surface's own value, never a blend with the (0, 0, 0, 0) clear, and a sample whose shader is not read exactly
    /// adds nothing (its value is not guessed). Alpha is the colour image's coverage: the alpha byte the colour image has on
    /// a transparent background, as given; RGB is 0 where that alpha is 0 or no sample is covered and supported. Straight,
    /// like the colour image (contract of issue 38).
    /// </summary>
    public static class MaterialPassResolve
    {
        /// <summary>
        /// OutputWidth × OutputHeight × 4 floats (R G B A, top row first) of <paramref name="pass"/>; a grey pass is written
        /// R = G = B. <paramref name="alpha"/> holds one byte per output pixel, top row first.
        /// </summary>
        public static float[] Resolve(RawFrame frame, MaterialPass pass, byte[] alpha) =>
            Resolve(frame, pass, alpha, new float[frame.OutputWidth * frame.OutputHeight * 4]);

        /// <summary><see cref="Resolve(RawFrame, MaterialPass, byte[])"/> into <paramref name="output"/> (the capture reuses one array per thread), which it returns.</summary>
        public static float[] Resolve(RawFrame frame, MaterialPass pass, byte[] alpha, float[] output)
        {
            var samples = pass.Samples(frame);
            Require(frame, "frame.Material" + char.ToUpperInvariant(pass.Name[0]) + pass.Name.Substring(1), samples, pass.FloatsPerSample);
            int k = frame.Supersampling, width = frame.Width, ow = frame.OutputWidth, oh = frame.OutputHeight, stride = frame.MaskBytesPerPixel, per = pass.FloatsPerSample;
            RawFrame.RequireOutput("alpha", alpha, (long)ow * oh, "bytes (1 per output pixel)");
            byte[] mask = frame.Mask, supported = frame.MaterialSupported;
            RawFrame.RequireOutput("output", output, (long)ow * oh * 4, "floats (4 per output pixel)");
            for (int oy = 0, o = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                for (int ox = 0; ox < ow; ox++, o += 4)
                {
                    var a = alpha[oy * ow + ox];
                    output[o] = output[o + 1] = output[o + 2] = 0;
                    output[o + 3] = a / 255f;
                    if (a == 0) continue; // (0, 0, 0, 0)
                    long weights = 0;
                    double r = 0, g = 0, b = 0;
                    for (int dy = 0; dy < k; dy++)
                    {
                        int p = (blockRow + dy) * width + ox * k;
                        for (int dx = 0; dx < k; dx++, p++)
                        {
                            int w = mask[p * stride] * supported[p];
                            if (w == 0) continue;
                            weights += w;
                            int s = p * per;
                            r += w * (double)samples[s];
                            if (per == 1) continue;
                            g += w * (double)samples[s + 1];
                            b += w * (double)samples[s + 2];
                        }
                    }
                    if (weights == 0) continue;
                    output[o] = (float)(r / weights);
                    output[o + 1] = per == 1 ? output[o] : (float)(g / weights);
                    output[o + 2] = per == 1 ? output[o] : (float)(b / weights);
                }
            }
            return output;
        }

        /// <summary>
        /// The coverage image: per output pixel round(mean of the block's <see cref="RawFrame.MaterialSupported"/> bytes),
        /// top row first — 255 where every sample's shader was read exactly, 0 where none was or nothing is drawn.
        /// </summary>
        public static byte[] Coverage(RawFrame frame)
        {
            Require(frame, null, null, 0);
            int k = frame.Supersampling, width = frame.Width, ow = frame.OutputWidth, oh = frame.OutputHeight;
            var supported = frame.MaterialSupported;
            var gray = new byte[ow * oh];
            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                for (int ox = 0; ox < ow; ox++)
                {
                    int sum = 0;
                    for (int dy = 0; dy < k; dy++)
                    {
                        int p = (blockRow + dy) * width + ox * k;
                        for (int dx = 0; dx < k; dx++) sum += supported[p + dx];
                    }
                    gray[oy * ow + ox] = MaskEncoding.AlphaOf(sum, k * k);
                }
            }
            return gray;
        }

        static void Require(RawFrame frame, string field, float[] samples, int perSample)
        {
            var problems = frame.Validate();
            if (frame.Mask == null) problems.Add(Missing("frame.Mask", "the mask pass (each sample's coverage weights its material values)"));
            long n = (long)frame.Width * frame.Height;
            if (frame.MaterialSupported == null) problems.Add(Missing("frame.MaterialSupported", "which samples' shaders the material passes read exactly"));
            else if (frame.MaterialSupported.Length != n) problems.Add(Length("frame.MaterialSupported", frame.MaterialSupported.Length, n, "1 byte per sample"));
            if (field != null)
            {
                if (samples == null) problems.Add(Missing(field, "this material pass, which the settings ask for"));
                else if (samples.Length != n * perSample) problems.Add(Length(field, samples.Length, n * perSample, perSample + " float(s) per sample"));
            }
            if (problems.Count > 0) throw new InvalidParameterException(problems);
        }

        static ValidationProblem Missing(string field, string what) =>
            new ValidationProblem(field, "null", "is required: the material passes read " + what + ".", "Read the pass back into this array first.");

        static ValidationProblem Length(string field, int actual, long expected, string layout) =>
            new ValidationProblem(field, "length " + actual.ToString(System.Globalization.CultureInfo.InvariantCulture),
                "does not match " + layout + " at the frame size (expected " + expected.ToString(System.Globalization.CultureInfo.InvariantCulture) + ").",
                "Pass the readback of a render texture of frame.Width × frame.Height.");
    }
}
