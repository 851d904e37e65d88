namespace NerfDatasetCreator
{
    /// <summary>
    /// <see cref="MattingDiagnostics"/> of one frame without resolving it: the very per-sample tests
    /// <see cref="DifferenceMatting.Resolve"/> makes (over white darker than over black; outside the mask and not exactly
    /// the clear pair), for frames whose mask and colour come from the same render. The capture counts here when the
    /// written colour is not that render (issue 32, R4-3): a motion-blurred image averages sub-frames at other poses
    /// than its mid-pose mask, and a lens image mixes the colour pair bilinearly while its mask is hit-or-miss, so both
    /// would report "stray background" at every moving or distorted edge. The sharp, wide frame before resampling is
    /// the render the mask belongs to.
    /// </summary>
    public static class MattingDiagnosis
    {
        /// <summary>The clear white, 1.0, as an IEEE half.</summary>
        const ushort WhiteHalf = 0x3C00;

        /// <summary>
        /// The diagnostics of every sample of <paramref name="frame"/>'s colour pair; the stray background only when the
        /// frame has a mask and <paramref name="checkBackground"/> (false when a sky is rendered into both halves).
        /// </summary>
        public static MattingDiagnostics Of(RawFrame frame, bool checkBackground)
        {
            var problems = frame.Validate();
            if (frame.ColorOverBlack == null || frame.ColorOverWhite == null)
                problems.Add(new ValidationProblem("frame.ColorOverBlack", "null", "is required: the matting diagnostics read the colour pass over black and over white.",
                    "Read back both colour renders into frame.ColorOverBlack and frame.ColorOverWhite."));
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            ushort[] black = frame.ColorOverBlack, white = frame.ColorOverWhite;
            byte[] mask = checkBackground ? frame.Mask : null;
            int maskBytes = frame.MaskBytesPerPixel;
            int samples = frame.Width * frame.Height; // the colour arrays hold 4 halves a sample, so this fits an int
            long darker = 0, stray = 0;
            float[] half = HalfFloat.Lookup;
            for (int s = 0; s < samples; s++)
            {
                int c = s * 4;
                float kr = half[black[c]], kg = half[black[c + 1]], kb = half[black[c + 2]];
                float tr = half[white[c]] - kr, tg = half[white[c + 1]] - kg, tb = half[white[c + 2]] - kb;
                if (tr < -MattingDiagnostics.DarkerTolerance || tg < -MattingDiagnostics.DarkerTolerance || tb < -MattingDiagnostics.DarkerTolerance) darker++;
                if (mask != null && mask[s * maskBytes] == 0
                    && (black[c] != 0 || black[c + 1] != 0 || black[c + 2] != 0 || white[c] != WhiteHalf || white[c + 1] != WhiteHalf || white[c + 2] != WhiteHalf))
                    stray++;
            }
            return new MattingDiagnostics { Samples = samples, DarkerOverWhite = darker, StrayBackground = stray, BackgroundChecked = mask != null };
        }
    }
}
