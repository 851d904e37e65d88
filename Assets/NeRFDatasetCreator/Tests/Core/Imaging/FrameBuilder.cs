namespace NerfDatasetCreator.Tests
{
    /// <summary>Builds raw frames in Unity's bottom-up layout from coordinates given top-down, as a person reads an image.</summary>
    internal static class FrameBuilder
    {
        public static RawFrame Frame(int outputWidth, int outputHeight, int k) => new RawFrame(outputWidth * k, outputHeight * k, k);

        /// <summary>Pixel index in the frame's arrays of the sample in column x, row y counted from the top.</summary>
        public static int Index(RawFrame frame, int x, int yFromTop) => (frame.Height - 1 - yFromTop) * frame.Width + x;

        public static RawFrame WithSrgb(this RawFrame frame)
        {
            frame.ColorSrgb = new byte[frame.Width * frame.Height * 4];
            frame.Mask = new byte[frame.Width * frame.Height * 4];
            return frame;
        }

        /// <summary>Marks a sample covered (mask R = 255, other mask bytes garbage to prove they are ignored) with an sRGB colour.</summary>
        public static void Cover(this RawFrame frame, int x, int yFromTop, byte r, byte g, byte b)
        {
            int p = Index(frame, x, yFromTop);
            frame.ColorSrgb[4 * p] = r;
            frame.ColorSrgb[4 * p + 1] = g;
            frame.ColorSrgb[4 * p + 2] = b;
            frame.ColorSrgb[4 * p + 3] = 17; // the lit shader's alpha: must be ignored
            frame.Mask[4 * p] = 255;
            frame.Mask[4 * p + 1] = 99;
            frame.Mask[4 * p + 3] = 7;
        }
    }
}
