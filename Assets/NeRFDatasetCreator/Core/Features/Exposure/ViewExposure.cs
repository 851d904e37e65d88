using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One view's exposure and white balance: the straight linear colour c of every pixel becomes
    /// c' = min(1, c · 2^<see cref="Ev"/> · gain) per channel (<see cref="ExposureWhiteBalance"/>). Written per frame as
    /// <c>exposure_ev</c> and <c>white_balance</c> [<see cref="R"/>, <see cref="G"/>, <see cref="B"/>].
    /// </summary>
    [Serializable]
    public struct ViewExposure
    {
        /// <summary>Exposure in stops: +1 doubles the light, −1 halves it.</summary>
        public double Ev;

        /// <summary>White-balance gains, linear multipliers per channel (1 = unchanged).</summary>
        public double R, G, B;

        public ViewExposure(double ev, double r, double g, double b)
        {
            Ev = ev;
            R = r;
            G = g;
            B = b;
        }

        /// <summary>No change: EV 0, gains 1.</summary>
        public static ViewExposure Identity => new ViewExposure(0, 1, 1, 1);

        /// <summary>The gain of channel 0 (R), 1 (G) or 2 (B).</summary>
        public double Gain(int channel) => channel == 0 ? R : channel == 1 ? G : B;

        /// <summary>The linear multiplier of channel 0, 1 or 2: 2^EV · gain.</summary>
        public double Scale(int channel) => Math.Pow(2, Ev) * Gain(channel);
    }
}
