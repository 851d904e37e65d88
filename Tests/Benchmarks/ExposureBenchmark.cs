using System;
using System.IO;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// The exposure stage's cost per 800×800 view (Documentation~/exposure.md): the in-place scaling of the finished RGBA
    /// (three 256-entry tables, built per view), the eXIf chunk insertion into the encoded PNG, and the check's
    /// comparison of a modified image with its clean one (after decoding, which the check figures count separately).
    /// Run with <c>--only exposure</c>; not in run-all's default sections.
    /// </summary>
    static class ExposureBenchmark
    {
        const int Size = 800;

        public static void Run(Action<string, double> record, Func<(string, Action)[], double[]> interleaved)
        {
            var random = new Random(5);
            var clean = new byte[Size * Size * 4];
            for (var i = 0; i < clean.Length; i++) clean[i] = (byte)(((i / 4) % Size) * 255 / Size + random.Next(8));
            var exposure = new ViewExposure(0.7, 1.1, 1, 0.9);
            var work = new byte[clean.Length];
            var png = PngWriter.Encode(clean, Size, Size, PngPixelFormat.Rgba8);
            var block = ExifExposure.Block(exposure.Ev);
            Buffer.BlockCopy(clean, 0, work, 0, clean.Length);
            ExposureWhiteBalance.ApplyRgba(work, exposure);
            var cleanImage = new PngImage(Size, Size, 8, PngInfo.ColorTypeRgba, clean);
            var modifiedImage = new PngImage(Size, Size, 8, PngInfo.ColorTypeRgba, (byte[])work.Clone());
            if (ExposureCheck.SamplesOutside(modifiedImage, cleanImage, exposure) != 0) throw new InvalidOperationException("the stage's output fails its own check");
            Console.WriteLine($"Exposure and white balance on one {Size}×{Size} RGBA view, ms:");
            var ms = interleaved(new (string, Action)[]
            {
                ("stage: tables + scale in place", () =>
                {
                    Buffer.BlockCopy(clean, 0, work, 0, clean.Length);
                    ExposureWhiteBalance.ApplyRgba(work, exposure);
                }),
                ("  of which copying the view back (not in the capture)", () => Buffer.BlockCopy(clean, 0, work, 0, clean.Length)),
                ("eXIf chunk into the encoded PNG", () => PngChunks.InsertExif(png, block)),
                ("check: modified vs clean (decoded)", () => ExposureCheck.SamplesOutside(modifiedImage, cleanImage, exposure)),
            });
            record("exposure.stage.ms", ms[0] - ms[1]);
            record("exposure.exif.ms", ms[2]);
            record("exposure.check.ms", ms[3]);
        }
    }
}
