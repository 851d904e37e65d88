using System;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// 3DGS trained with <c>--train_test_exp</c> (exposure compensation: the left half of each test image is used to fit
    /// the test view's exposure, the right half to score it) renders every view and its <c>gt</c> as the right half only:
    /// <c>rendering[..., rendering.shape[-1] // 2:]</c>, graphdeco-inria/gaussian-splatting render.py (182afc9) lines 41–43.
    /// A 3DGS render of width W − ⌊W/2⌋ and the full height is that half, and is scored against columns ⌊W/2⌋ … W − 1 of
    /// the dataset's image, mask, depth and normals — what 3DGS's metrics.py compares, its <c>gt/</c> being cropped alike.
    /// </summary>
    public static class TrainTestExposureCrop
    {
        /// <summary>The first column of the dataset's images the renders hold: ⌊W/2⌋ when every 3DGS render is the right half, else 0.</summary>
        public static int FirstColumn(EvaluationDataset dataset, RenderSet renders)
        {
            if (renders.Layout != RenderLayout.GaussianSplatting || renders.Views.Count == 0) return 0;
            foreach (var view in renders.Views)
            {
                PngInfo truth, render;
                try
                {
                    truth = PngInfo.Read(dataset.Frames[view.FrameIndex].ImagePath);
                    render = PngInfo.Read(view.ColourPath);
                }
                catch (System.IO.InvalidDataException) { return 0; } // CheckSizes reports it
                if (truth.Width < 2 || render.Height != truth.Height || render.Width != truth.Width - truth.Width / 2) return 0;
            }
            return PngInfo.Read(dataset.Frames[renders.Views[0].FrameIndex].ImagePath).Width / 2;
        }

        /// <summary>Columns <paramref name="first"/> … W − 1 of <paramref name="png"/> (the image itself when <paramref name="first"/> is 0).</summary>
        public static PngImage Columns(PngImage png, int first)
        {
            if (first <= 0) return png;
            if (first >= png.Width) throw new ArgumentOutOfRangeException(nameof(first));
            var bytesPerPixel = png.Channels * (png.BitDepth / 8);
            var width = png.Width - first;
            var samples = new byte[width * png.Height * bytesPerPixel];
            for (var y = 0; y < png.Height; y++)
                Buffer.BlockCopy(png.Samples, (y * png.Width + first) * bytesPerPixel, samples, y * width * bytesPerPixel, width * bytesPerPixel);
            return new PngImage(width, png.Height, png.BitDepth, png.ColorType, samples);
        }
    }
}
