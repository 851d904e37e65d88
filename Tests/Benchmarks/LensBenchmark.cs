using System;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// The lens stage's cost per 800×800 view at supersampling 2 (Documentation~/lens-distortion.md): the sample map
    /// (built once per capture and frame size), then per view the resampling of a wide pinhole render into the distorted
    /// frame — the matting pair (two half-float RGBA renders), the R8 mask, depth and normals, as a lens capture renders
    /// every pass at the supersampled size — into the writer thread's reused arrays, as the capture calls it. The wide
    /// render is a shaded sphere filling most of the frame. Run with <c>--only lens</c>; not in run-all's default sections.
    /// </summary>
    static class LensBenchmark
    {
        const int Size = 800, K = 2;

        public static void Run(Action<string, double> record, Func<(string, Action)[], double[]> interleaved)
        {
            var lens = LensDistortion.OpenCv(-0.12, 0.02, 0, 0);
            var output = CameraIntrinsics.FromVerticalFov(50, Size, Size);
            var cover = LensCapture.WideRender(lens, output);
            var resampler = new LensResampler(lens, output, cover);
            var all = Wide(cover.Width * K, cover.Height * K, data: true);
            var colourOnly = Wide(cover.Width * K, cover.Height * K, data: false);
            resampler.Map(K);
            Console.WriteLine($"Lens resampling of one {Size}×{Size} view at supersampling {K} (OpenCV k1 −0.12, k2 0.02; wide render {cover.Width}×{cover.Height}×{K}), ms:");
            var ms = interleaved(new (string, Action)[]
            {
                ("sample map (once per capture and frame size)", () => LensSampleMap.Build(lens, output, cover, K)),
                ("resample colour pair + mask + depth + normals", () => resampler.Resample(all, reuseThreadBuffers: true)),
                ("resample colour pair + mask", () => resampler.Resample(colourOnly, reuseThreadBuffers: true)),
            });
            record("lens.map.ms", ms[0]);
            record("lens.all.ms", ms[1]);
            record("lens.colour.ms", ms[2]);
        }

        /// <summary>A wide render, bottom row first: a Lambert-shaded sphere over the clear (black / white), its mask, z-depth and normals.</summary>
        static RawFrame Wide(int w, int h, bool data)
        {
            int n = w * h;
            var frame = new RawFrame(w, h, K)
            {
                ColorOverBlack = new ushort[n * 4], ColorOverWhite = new ushort[n * 4], Mask = new byte[n], MaskBytesPerPixel = 1,
                Depth = data ? new float[n] : null, Normals = data ? new float[n * 4] : null,
            };
            double cx = w / 2.0, cy = h / 2.0, r = 0.45 * Math.Min(w, h);
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    int p = y * w + x;
                    double nx = (x + 0.5 - cx) / r, ny = (y + 0.5 - cy) / r, d2 = nx * nx + ny * ny;
                    if (d2 >= 1)
                    {
                        frame.ColorOverWhite[p * 4] = frame.ColorOverWhite[p * 4 + 1] = frame.ColorOverWhite[p * 4 + 2] = 0x3C00; // 1.0
                        continue;
                    }
                    var nz = Math.Sqrt(1 - d2);
                    var shade = 0.3 + 0.7 * Math.Max(0, 0.3 * nx + 0.4 * ny + 0.85 * nz);
                    for (var c = 0; c < 3; c++)
                        frame.ColorOverBlack[p * 4 + c] = frame.ColorOverWhite[p * 4 + c] = HalfFloat.FromFloat((float)(shade * (0.4 + 0.2 * c)));
                    frame.ColorOverBlack[p * 4 + 3] = frame.ColorOverWhite[p * 4 + 3] = 0x3C00;
                    frame.Mask[p] = 255;
                    if (!data) continue;
                    frame.Depth[p] = (float)(4 - nz);
                    frame.Normals[p * 4] = (float)nx;
                    frame.Normals[p * 4 + 1] = (float)ny;
                    frame.Normals[p * 4 + 2] = (float)nz;
                }
            return frame;
        }
    }
}
