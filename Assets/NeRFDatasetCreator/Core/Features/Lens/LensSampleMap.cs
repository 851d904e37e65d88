using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where each sample of the distorted frame looks in the wide pinhole render, computed once per capture (one Newton
    /// inverse per sample is the costly part of resampling). For output sample (xs, ys) — top-left origin, supersampled
    /// grid of factor k — its centre in output pixels is u = (xs + ½)/k, v = (ys + ½)/k; the lens's normalised point is
    /// x_d = (u − cx)/fx, y_d = (v − cy)/fy; <see cref="LensDistortion.Undistort"/> gives the ray (x, y, 1) in OpenCV
    /// camera axes; the wide pinhole (focal F, principal point (Cx, Cy), the same camera) images that ray at
    /// (F·x + Cx, F·y + Cy), i.e. k·(F·x + Cx), k·(F·y + Cy) on its supersampled grid. Both frames are stored the way
    /// readbacks are, bottom row first, so the map is kept in that order too, with the pixel-centre-at-½ convention.
    /// </summary>
    public sealed class LensSampleMap
    {
        readonly float[] _x, _y;

        LensSampleMap(int width, int height, int wideWidth, int wideHeight, float[] x, float[] y)
        {
            Width = width; Height = height; WideWidth = wideWidth; WideHeight = wideHeight; _x = x; _y = y;
        }

        /// <summary>The distorted frame's sample grid (output size × k).</summary>
        public int Width { get; }
        public int Height { get; }

        /// <summary>The wide render's sample grid (wide size × k).</summary>
        public int WideWidth { get; }
        public int WideHeight { get; }

        /// <summary>Samples whose ray the lens does not image (never for a frame <see cref="LensPinholeCover.For"/> accepted); they stay empty.</summary>
        public int Unmapped { get; private set; }

        public static LensSampleMap Build(LensDistortion lens, CameraIntrinsics output, LensPinholeCover wide, int supersampling)
        {
            int k = supersampling, w = output.Width * k, h = output.Height * k, ww = wide.Width * k, wh = wide.Height * k;
            var x = new float[(long)w * h];
            var y = new float[(long)w * h];
            var unmapped = 0;
            double f = wide.Focal, cx = wide.Cx, cy = wide.Cy;
            for (var ys = 0; ys < h; ys++)
            {
                var row = (h - 1 - ys) * w; // bottom row first
                var yd = ((ys + 0.5) / k - output.Cy) / output.FlY;
                for (var xs = 0; xs < w; xs++)
                {
                    var xd = ((xs + 0.5) / k - output.Cx) / output.FlX;
                    var p = row + xs;
                    if (!lens.Undistort(xd, yd, out var rx, out var ry))
                    {
                        x[p] = y[p] = float.NaN;
                        unmapped++;
                        continue;
                    }
                    x[p] = (float)(k * (f * rx + cx));
                    // Top-down continuous v → bottom-up: a centre at v = j + ½ from the top is at H − v from the bottom.
                    y[p] = (float)(wh - k * (f * ry + cy));
                }
            }
            return new LensSampleMap(w, h, ww, wh, x, y) { Unmapped = unmapped };
        }

        /// <summary>The continuous wide-grid position (bottom-up rows, sample centres at +½) output sample <paramref name="p"/> reads; NaN when unmapped.</summary>
        public void Position(int p, out float x, out float y)
        {
            x = _x[p];
            y = _y[p];
        }

        /// <summary>
        /// The four wide samples around output sample <paramref name="p"/> for bilinear weights: index of the lower-left
        /// one, the steps to its right and upper neighbours (0 where clamped at the render's edge), the weights of those
        /// neighbours, and the nearest sample. False for an unmapped sample.
        /// </summary>
        public bool Locate(int p, out int i00, out int dx, out int dy, out float ax, out float ay, out int nearest)
        {
            float x = _x[p] - 0.5f, y = _y[p] - 0.5f;
            if (float.IsNaN(x) || float.IsNaN(y)) { i00 = dx = dy = nearest = 0; ax = ay = 0; return false; }
            int x0 = (int)Math.Floor(x), y0 = (int)Math.Floor(y);
            ax = x - x0;
            ay = y - y0;
            // Clamp to the edge: the frame's border rays lie within the render, at most half a sample outside the outer centres.
            if (x0 < 0) { x0 = 0; ax = 0; }
            if (y0 < 0) { y0 = 0; ay = 0; }
            if (x0 >= WideWidth - 1) { x0 = WideWidth - 1; ax = 0; }
            if (y0 >= WideHeight - 1) { y0 = WideHeight - 1; ay = 0; }
            dx = x0 < WideWidth - 1 ? 1 : 0;
            dy = y0 < WideHeight - 1 ? WideWidth : 0;
            i00 = y0 * WideWidth + x0;
            nearest = i00 + (ax >= 0.5f ? dx : 0) + (ay >= 0.5f ? dy : 0);
            return true;
        }
    }
}
