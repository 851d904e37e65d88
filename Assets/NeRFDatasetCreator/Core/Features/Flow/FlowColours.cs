using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Pictures of a flow field for people (never read back by anything): the Middlebury colour code of Baker et al., "A
    /// Database and Evaluation Methodology for Optical Flow" (ICCV 2007 / IJCV 2011) — hue is the direction, saturation
    /// the length relative to the longest vector, as Scharstein's <c>colorcode.cpp</c> (flow-code, vision.middlebury.edu)
    /// computes it and RAFT's <c>core/utils/flow_viz.py</c> ports it (Documentation~/maintainers/flow.md) — and the
    /// occlusion states in flat colours.
    /// </summary>
    public static class FlowColours
    {
        // colorcode.cpp's makecolorwheel: RY 15, YG 6, GC 4, CB 11, BM 13, MR 6 steps between the six hues (55 colours).
        static readonly byte[,] Wheel = MakeWheel();

        static byte[,] MakeWheel()
        {
            int[] steps = { 15, 6, 4, 11, 13, 6 };
            var wheel = new byte[55, 3];
            var k = 0;
            for (var segment = 0; segment < 6; segment++)
                for (var i = 0; i < steps[segment]; i++, k++)
                {
                    // 255·i/n rounded down (integer division in colorcode.cpp, np.floor in flow_viz.py).
                    int up = 255 * i / steps[segment], down = 255 - up;
                    int r, g, b;
                    switch (segment)
                    {
                        case 0: r = 255; g = up; b = 0; break;   // red → yellow
                        case 1: r = down; g = 255; b = 0; break; // yellow → green
                        case 2: r = 0; g = 255; b = up; break;   // green → cyan
                        case 3: r = 0; g = down; b = 255; break; // cyan → blue
                        case 4: r = up; g = 0; b = 255; break;   // blue → magenta
                        default: r = 255; g = 0; b = down; break; // magenta → red
                    }
                    wheel[k, 0] = (byte)r;
                    wheel[k, 1] = (byte)g;
                    wheel[k, 2] = (byte)b;
                }
            return wheel;
        }

        /// <summary>
        /// The colour of flow (fx, fy), already divided by the longest vector (so |f| ≤ 1 inside the range), as
        /// colorcode.cpp's computeColor: angle atan2(−fy, −fx) picks two neighbouring wheel colours, blended linearly;
        /// inside the unit circle desaturated towards white by the length, outside darkened to 75 %. RGB order.
        /// </summary>
        public static void Colour(double fx, double fy, byte[] rgb, int offset)
        {
            const int n = 55;
            var radius = Math.Sqrt(fx * fx + fy * fy);
            var a = Math.Atan2(-fy, -fx) / Math.PI;
            var fk = (a + 1) / 2 * (n - 1);
            var k0 = (int)fk;
            var k1 = (k0 + 1) % n;
            var f = fk - k0;
            for (var c = 0; c < 3; c++)
            {
                var col = (1 - f) * Wheel[k0, c] / 255.0 + f * Wheel[k1, c] / 255.0;
                col = radius <= 1 ? 1 - radius * (1 - col) : col * 0.75;
                rgb[offset + c] = (byte)(int)(255 * col);
            }
        }

        /// <summary>
        /// An RGB picture (row-major, 3 bytes a pixel) of <paramref name="flow"/> ((dx, dy) per pixel, NaN = none):
        /// vectors divided by <paramref name="maxRadius"/> (≤ 0: by the longest finite vector, as flow_viz.py's
        /// flow_to_color does), pixels without flow black (colorcode.cpp's unknown flow).
        /// </summary>
        public static byte[] Picture(float[] flow, int width, int height, double maxRadius = 0)
        {
            if (flow == null || flow.Length != 2 * width * height) throw new ArgumentException("flow holds (dx, dy) for each of the " + width + " × " + height + " pixels.", nameof(flow));
            if (!(maxRadius > 0))
            {
                maxRadius = 0;
                for (var p = 0; p < width * height; p++)
                {
                    double dx = flow[2 * p], dy = flow[2 * p + 1];
                    if (double.IsNaN(dx) || double.IsNaN(dy)) continue;
                    maxRadius = Math.Max(maxRadius, Math.Sqrt(dx * dx + dy * dy));
                }
            }
            var scale = maxRadius > 0 ? 1 / maxRadius : 1;
            var rgb = new byte[3 * width * height];
            for (var p = 0; p < width * height; p++)
            {
                double dx = flow[2 * p], dy = flow[2 * p + 1];
                if (double.IsNaN(dx) || double.IsNaN(dy)) continue;
                Colour(dx * scale, dy * scale, rgb, 3 * p);
            }
            return rgb;
        }

        /// <summary>The colour of each <see cref="FlowState"/> in <see cref="Occlusion"/>'s picture: no surface, visible, hidden, outside.</summary>
        public static readonly byte[][] StateColours =
        {
            new byte[] { 0, 0, 0 },       // NoSurface: black
            new byte[] { 235, 235, 235 }, // Visible: near white
            new byte[] { 220, 40, 30 },   // Hidden at the other frame: red
            new byte[] { 40, 90, 220 },   // Outside the other frame's image: blue
        };

        /// <summary>An RGB picture of the occlusion states (<see cref="FlowState"/> per pixel) in <see cref="StateColours"/>.</summary>
        public static byte[] Occlusion(byte[] state, int width, int height)
        {
            if (state == null || state.Length != width * height) throw new ArgumentException("state holds one FlowState for each of the " + width + " × " + height + " pixels.", nameof(state));
            var rgb = new byte[3 * width * height];
            for (var p = 0; p < state.Length; p++)
            {
                var colour = StateColours[state[p] < StateColours.Length ? state[p] : 0];
                rgb[3 * p] = colour[0];
                rgb[3 * p + 1] = colour[1];
                rgb[3 * p + 2] = colour[2];
            }
            return rgb;
        }
    }
}
