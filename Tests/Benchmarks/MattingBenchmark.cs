using System;
using System.Diagnostics;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// The CPU side of difference matting: one 800×800 output from two 1600×1600 half-float colour renders (k = 2),
    /// against the single-render path it replaced (sRGB bytes + mask). The second render on the GPU and its readback
    /// cannot be measured here (no Unity); this is the post-processing cost only.
    /// </summary>
    static class MattingBenchmark
    {
        const int Size = 800, K = 2, Rounds = 15;

        public static void Run()
        {
            int w = Size * K;
            var random = new Random(7);
            var black = new ushort[w * w * 4];
            var white = new ushort[w * w * 4];
            var srgb = new byte[w * w * 4];
            var mask = new byte[w * w];
            for (int y = 0; y < w; y++)
                for (int x = 0; x < w; x++)
                {
                    int i = y * w + x;
                    double dx = x - w / 2.0, dy = y - w / 2.0;
                    bool inside = dx * dx + dy * dy < 0.16 * w * w;
                    // Half bits of values in [0.25, 0.5): exponent −2 (0x3400) plus a random mantissa.
                    for (int c = 0; c < 3; c++)
                    {
                        ushort value = (ushort)(0x3400 | random.Next(1024));
                        black[i * 4 + c] = inside ? value : (ushort)0;
                        white[i * 4 + c] = inside ? value : (ushort)0x3C00;
                        srgb[i * 4 + c] = inside ? (byte)random.Next(256) : (byte)0;
                    }
                    mask[i] = inside ? (byte)255 : (byte)0;
                }
            var pair = new RawFrame(w, w, K) { ColorOverBlack = black, ColorOverWhite = white };
            var single = new RawFrame(w, w, K) { ColorSrgb = srgb, Mask = mask, MaskBytesPerPixel = 1 };
            var rgba = new byte[Size * Size * 4];

            Console.WriteLine($"Colour resolve, one {Size}×{Size} view from {w}×{w} readbacks (k = {K}), single thread, {Rounds} rounds, fastest / median ms:");
            Report("  difference matting (2 × RGBA half)", () => DifferenceMatting.Resolve(pair, rgba));
            Report("  mask as alpha (RGBA8 sRGB + R8)   ", () => StraightAlpha.Resolve(single, rgba));
            Console.WriteLine($"  readback per view: matting {2L * black.Length * 2 / 1e6:0.0} MB, before {(srgb.Length + mask.Length) / 1e6:0.0} MB");
            Console.WriteLine();
        }

        static void Report(string name, Action action)
        {
            action(); // warm-up: tables, JIT
            var times = new double[Rounds];
            for (int r = 0; r < Rounds; r++)
            {
                var clock = Stopwatch.StartNew();
                action();
                times[r] = clock.Elapsed.TotalMilliseconds;
            }
            Array.Sort(times);
            Console.WriteLine($"{name}: {times[0],7:0.0} / {times[Rounds / 2],7:0.0}");
        }
    }
}
