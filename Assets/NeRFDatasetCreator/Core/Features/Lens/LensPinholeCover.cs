using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The pinhole render a distorted frame is resampled from (issue 27's capture side): it must see every ray of the
    /// distorted frame, and sample at least as densely as the output everywhere. Bounds: every border pixel edge of
    /// the distorted frame is undistorted (for the lenses <see cref="LensDistortion.Undistort"/> accepts the
    /// extremes lie on the border). Density: an output step of one pixel moves the ideal point by J⁻¹/f, where J is
    /// the distortion's Jacobian, so the pinhole focal must be f·max σ_max(J) over the frame (1 for barrel
    /// distortion, whose Jacobian shrinks outward; more for pincushion). The render is refused beyond
    /// <see cref="MaxFovDegrees"/> or <see cref="CameraIntrinsics.MaxSize"/>: a wider fisheye needs several renders.
    /// </summary>
    public sealed class LensPinholeCover
    {
        /// <summary>The widest pinhole render accepted: tan 75° ≈ 3.7, so the periphery is already sampled ~14× more finely than the centre.</summary>
        public const double MaxFovDegrees = 150;

        LensPinholeCover(double focal, double left, double right, double top, double bottom, int width, int height, double cx, double cy)
        {
            Focal = focal; Left = left; Right = right; Top = top; Bottom = bottom; Width = width; Height = height; Cx = cx; Cy = cy;
        }

        /// <summary>Pinhole focal length in pixels (both axes).</summary>
        public double Focal { get; }

        /// <summary>Normalised extents seen by the distorted frame: x from −Left to Right, y (down) from −Top to Bottom.</summary>
        public double Left { get; }
        public double Right { get; }
        public double Top { get; }
        public double Bottom { get; }

        /// <summary>The pinhole render's size and principal point (pixels, top-left corner at 0).</summary>
        public int Width { get; }
        public int Height { get; }
        public double Cx { get; }
        public double Cy { get; }

        /// <summary>
        /// The cover of the frame <paramref name="k"/> through <paramref name="lens"/> (pixel units: fx = k.FlX, fy = k.FlY;
        /// the pinhole uses square pixels at the larger focal). Throws <see cref="InvalidParameterException"/> when the
        /// frame holds rays the lens cannot undistort, or the render would exceed the caps.
        /// </summary>
        public static LensPinholeCover For(LensDistortion lens, CameraIntrinsics k)
        {
            if (lens == null) throw new ArgumentNullException(nameof(lens));
            if (k == null) throw new ArgumentNullException(nameof(k));
            double left = 0, right = 0, top = 0, bottom = 0;
            void Edge(double px, double py)
            {
                double xd = (px - k.Cx) / k.FlX, yd = (py - k.Cy) / k.FlY;
                if (!lens.Undistort(xd, yd, out var x, out var y))
                    throw new InvalidParameterException(new[] { new ValidationProblem("lens", lens.Describe(),
                        "images no ray at pixel (" + px + ", " + py + ") of the " + k.Width + "×" + k.Height + " frame: the lens folds over (or, a fisheye, looks 90° or more off its axis) before the frame's edge.",
                        "Use smaller coefficients or a narrower field of view.") });
                left = Math.Max(left, -x); right = Math.Max(right, x); top = Math.Max(top, -y); bottom = Math.Max(bottom, y);
            }
            for (var i = 0; i <= k.Width; i++) { Edge(i, 0); Edge(i, k.Height); }
            for (var j = 0; j <= k.Height; j++) { Edge(0, j); Edge(k.Width, j); }

            // max σ_max(J) on a grid of pixel corners (J from LensDistortion.Jacobian at the ideal point).
            var stretch = 1.0;
            var step = Math.Max(1, Math.Max(k.Width, k.Height) / 64);
            for (var j = 0; j <= k.Height; j += step)
                for (var i = 0; i <= k.Width; i += step)
                {
                    lens.Undistort((i - k.Cx) / k.FlX, (j - k.Cy) / k.FlY, out var x, out var y);
                    stretch = Math.Max(stretch, LargestSingularValue(lens, x, y));
                }
            var focal = Math.Max(k.FlX, k.FlY) * stretch;

            var fovX = (Math.Atan(left) + Math.Atan(right)) * 180 / Math.PI;
            var fovY = (Math.Atan(top) + Math.Atan(bottom)) * 180 / Math.PI;
            // A millionth of a pixel absorbs rounding (a lens without distortion gives exactly W × H).
            var width = Math.Ceiling(focal * (left + right) - 1e-6);
            var height = Math.Ceiling(focal * (top + bottom) - 1e-6);
            if (fovX > MaxFovDegrees || fovY > MaxFovDegrees || width > CameraIntrinsics.MaxSize || height > CameraIntrinsics.MaxSize)
                throw new InvalidParameterException(new[] { new ValidationProblem("lens", lens.Describe(),
                    "needs a pinhole render of " + Format(fovX) + "° × " + Format(fovY) + "° at " + Format(width) + " × " + Format(height) +
                    " pixels to cover the " + k.Width + "×" + k.Height + " frame; the caps are " + MaxFovDegrees + "° and " + CameraIntrinsics.MaxSize + " pixels.",
                    "Use a smaller output resolution or a narrower field of view (a fisheye beyond 150° needs several renders, which are not built yet).") });
            return new LensPinholeCover(focal, left, right, top, bottom, (int)width, (int)height, focal * left, focal * top);
        }

        /// <summary>
        /// The same render made symmetric about its centre (principal point at exactly (W/2, H/2)), which is what a
        /// Unity camera renders from a vertical field of view and an aspect alone (no lens shift, no projection
        /// matrix of our own): each half-extent becomes the larger of its two sides, the focal stays. Throws like
        /// <see cref="For"/> when the symmetric render exceeds the caps.
        /// </summary>
        public LensPinholeCover Centred()
        {
            double hx = Math.Max(Left, Right), hy = Math.Max(Top, Bottom);
            var width = Math.Ceiling(2 * Focal * hx - 1e-6);
            var height = Math.Ceiling(2 * Focal * hy - 1e-6);
            // The visible half-extents of the rounded-up size, which the field of view is built from.
            hx = width / (2 * Focal);
            hy = height / (2 * Focal);
            var fovX = 2 * Math.Atan(hx) * 180 / Math.PI;
            var fovY = 2 * Math.Atan(hy) * 180 / Math.PI;
            if (fovX > MaxFovDegrees || fovY > MaxFovDegrees || width > CameraIntrinsics.MaxSize || height > CameraIntrinsics.MaxSize)
                throw new InvalidParameterException(new[] { new ValidationProblem("lens", "wide render " + Format(width) + " × " + Format(height),
                    "would span " + Format(fovX) + "° × " + Format(fovY) + "° centred on the axis; the caps are " + MaxFovDegrees + "° and " + CameraIntrinsics.MaxSize + " pixels.",
                    "Use a smaller output resolution, a narrower field of view or a milder lens.") });
            return new LensPinholeCover(Focal, hx, hx, hy, hy, (int)width, (int)height, width / 2, height / 2);
        }

        /// <summary>Vertical field of view of a centred render in degrees (Unity's <c>Camera.fieldOfView</c>): 2·atan(H / 2f).</summary>
        public double VerticalFovDegrees => 2 * Math.Atan(Height / (2 * Focal)) * 180 / Math.PI;

        /// <summary>Horizontal field of view in degrees of a centred render: 2·atan(W / 2f).</summary>
        public double HorizontalFovDegrees => 2 * Math.Atan(Width / (2 * Focal)) * 180 / Math.PI;

        static double LargestSingularValue(LensDistortion lens, double x, double y)
        {
            lens.Jacobian(x, y, out var a, out var b, out var c, out var d);
            // σ_max² is the larger eigenvalue of JᵀJ.
            double p = a * a + c * c, q = a * b + c * d, r = b * b + d * d;
            return Math.Sqrt(0.5 * (p + r) + Math.Sqrt(0.25 * (p - r) * (p - r) + q * q));
        }

        static string Format(double v) => Math.Round(v, 1).ToString(System.Globalization.CultureInfo.InvariantCulture);
    }
}
