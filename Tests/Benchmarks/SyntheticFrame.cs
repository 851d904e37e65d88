using System;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// A render-like raw frame: a textured, Lambert-shaded sphere on a (0,0,0,0) clear, as the capture layer would
    /// read it back (bottom-up, supersampled), with the matching mask, eye depth and normal passes.
    /// </summary>
    static class SyntheticFrame
    {
        /// <summary>
        /// The same scene in the capture's own layout: colour rendered twice at k× the output size, over black and
        /// over white, as half floats (difference matting, pixels.md §2) with a 1-byte (R8) mask; depth and Unity
        /// world normals rendered at the output size (supersampling 1) — what DatasetViewWriter hands to Core.
        /// </summary>
        public static (RawFrame Colour, RawFrame Data) CaptureLayout(int outputSize, int k, double noise = 0.02)
        {
            var linear = Sphere(outputSize, k, linearFloatColour: true, noise: noise);
            int samples = linear.Width * linear.Height;
            var black = new ushort[samples * 4];
            var white = new ushort[samples * 4];
            var r8 = new byte[samples];
            for (int i = 0; i < samples; i++)
            {
                bool covered = linear.Mask[4 * i] != 0;
                r8[i] = linear.Mask[4 * i];
                for (int c = 0; c < 3; c++)
                {
                    ushort h = Half(linear.ColorLinear[4 * i + c]);
                    black[4 * i + c] = covered ? h : (ushort)0;
                    white[4 * i + c] = covered ? h : (ushort)0x3C00; // 1.0: the white clear
                }
            }
            var colour = new RawFrame(linear.Width, linear.Height, k) { ColorOverBlack = black, ColorOverWhite = white, Mask = r8, MaskBytesPerPixel = 1 };
            var atOutput = Sphere(outputSize, 1, noise: noise);
            var data = new RawFrame(outputSize, outputSize, 1) { Depth = atOutput.Depth, Normals = atOutput.Normals, NormalsInUnityWorld = true };
            return (colour, data);
        }

        /// <summary>IEEE half bits of a value clamped to [0, 1], rounded to nearest (setup only, not timed).</summary>
        static ushort Half(float value)
        {
            if (!(value > 0)) return 0;
            if (value >= 1) return 0x3C00;
            int bits = BitConverter.ToInt32(BitConverter.GetBytes(value), 0);
            int exponent = ((bits >> 23) & 0xFF) - 127 + 15, mantissa = (bits & 0x7FFFFF) | 0x800000;
            if (exponent <= 0) return (ushort)((mantissa + (1 << (13 - exponent))) >> (14 - exponent)); // subnormal
            return (ushort)(((exponent << 10) | ((mantissa & 0x7FFFFF) >> 13)) + ((mantissa >> 12) & 1));
        }

        public static RawFrame Sphere(int outputSize, int k, bool linearFloatColour = false, double noise = 0.02)
        {
            int size = outputSize * k;
            var frame = new RawFrame(size, size, k)
            {
                Mask = new byte[size * size * 4],
                Depth = new float[size * size],
                Normals = new float[size * size * 4],
            };
            if (linearFloatColour) frame.ColorLinear = new float[size * size * 4];
            else frame.ColorSrgb = new byte[size * size * 4];

            var random = new SeededRandom(42);
            double radius = size * 0.38, cameraDistance = 4.0, sphereRadius = 1.0;
            for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++)
            {
                double u = (x + 0.5 - size / 2.0) / radius, v = (y + 0.5 - size / 2.0) / radius;
                double rr = u * u + v * v;
                if (rr >= 1) continue;
                double nz = Math.Sqrt(1 - rr);
                // Texture: stripes; light from the upper left; optional grain standing in for fine texture detail.
                double stripes = 0.5 + 0.5 * Math.Sin(12 * Math.Atan2(v, u)) * Math.Cos(9 * v);
                double light = Math.Max(0, -0.4 * u + 0.5 * v + 0.77 * nz);
                double grain = (random.NextDouble() - 0.5) * noise;
                double r = (0.15 + 0.7 * stripes) * light + grain, g = (0.3 + 0.4 * stripes) * light + grain, b = 0.55 * light + grain;

                int p = y * size + x;
                if (frame.ColorLinear != null)
                {
                    frame.ColorLinear[4 * p] = (float)r;
                    frame.ColorLinear[4 * p + 1] = (float)g;
                    frame.ColorLinear[4 * p + 2] = (float)b;
                    frame.ColorLinear[4 * p + 3] = 1f;
                }
                else
                {
                    frame.ColorSrgb[4 * p] = Srgb.EncodeByteExact(r);
                    frame.ColorSrgb[4 * p + 1] = Srgb.EncodeByteExact(g);
                    frame.ColorSrgb[4 * p + 2] = Srgb.EncodeByteExact(b);
                    frame.ColorSrgb[4 * p + 3] = 255;
                }
                frame.Mask[4 * p] = 255;
                frame.Mask[4 * p + 1] = 255;
                frame.Mask[4 * p + 2] = 255;
                frame.Mask[4 * p + 3] = 255;
                frame.Depth[p] = (float)(cameraDistance - sphereRadius * nz);
                frame.Normals[4 * p] = (float)u;
                frame.Normals[4 * p + 1] = (float)v;
                frame.Normals[4 * p + 2] = (float)nz;
            }
            return frame;
        }
    }
}
