using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Pinhole intrinsics in every form the loaders read, from Unity's vertical field of view and the output size.
    /// <c>camera_angle_x</c> is the horizontal field of view (nerf_synthetic; the original plugin wrote the vertical
    /// one), focal lengths are in pixels, and the principal point is in continuous pixel coordinates with the image's
    /// top-left corner at (0, 0) — (W/2, H/2) without lens shift.
    /// </summary>
    [Serializable]
    public sealed class CameraIntrinsics
    {
        CameraIntrinsics(int width, int height, double flX, double flY, double cx, double cy)
        {
            Width = width;
            Height = height;
            FlX = flX;
            FlY = flY;
            Cx = cx;
            Cy = cy;
        }

        public int Width { get; }
        public int Height { get; }

        /// <summary>Focal length along x, in pixels.</summary>
        public double FlX { get; }

        /// <summary>Focal length along y, in pixels; equals <see cref="FlX"/> for square pixels.</summary>
        public double FlY { get; }

        public double Cx { get; }
        public double Cy { get; }

        /// <summary>Horizontal field of view in radians: <c>camera_angle_x</c>.</summary>
        public double CameraAngleX => 2 * Math.Atan(Width / (2 * FlX));

        /// <summary>Vertical field of view in radians: <c>camera_angle_y</c>.</summary>
        public double CameraAngleY => 2 * Math.Atan(Height / (2 * FlY));

        public const int MinSize = 1;
        public const int MaxSize = 16384;

        /// <summary>
        /// Intrinsics of a Unity camera with <c>fieldOfView</c> = <paramref name="verticalFovDegrees"/> rendering
        /// W×H square pixels. <paramref name="lensShiftX"/> and <paramref name="lensShiftY"/> are Unity's
        /// <c>Camera.lensShift</c> (fractions of the sensor size). A shift is an off-axis frustum: projection
        /// entries m02 = 2·shiftX and m12 = 2·shiftY, so a frustum shifted right and up sees more to the right and
        /// above, and the optical axis lands left of and below the image centre: cx = W/2 − shiftX·W,
        /// cy = H/2 + shiftY·H (rows run downwards).
        /// </summary>
        public static CameraIntrinsics FromVerticalFov(double verticalFovDegrees, int width, int height, double lensShiftX = 0, double lensShiftY = 0)
        {
            InvalidParameterException.ThrowIfAny(
                !(verticalFovDegrees > 0 && verticalFovDegrees < 180)
                    ? new ValidationProblem("verticalFovDegrees", ValidationProblem.Format(verticalFovDegrees), "must be more than 0 and less than 180 degrees.", "Use Unity's Camera.fieldOfView, e.g. 60.")
                    : null,
                ValidationProblem.OutsideRange("width", width, MinSize, MaxSize),
                ValidationProblem.OutsideRange("height", height, MinSize, MaxSize),
                ValidationProblem.OutsideRange("lensShiftX", lensShiftX, -1, 1),
                ValidationProblem.OutsideRange("lensShiftY", lensShiftY, -1, 1));
            var focal = height / (2 * Math.Tan(verticalFovDegrees * Math.PI / 360.0));
            return new CameraIntrinsics(width, height, focal, focal, width / 2.0 - lensShiftX * width, height / 2.0 + lensShiftY * height);
        }

        /// <summary>Unity's vertical field of view in degrees for a horizontal one in radians and an aspect W/H.</summary>
        public static double VerticalFovDegreesFromHorizontal(double cameraAngleX, int width, int height) =>
            2 * Math.Atan(Math.Tan(cameraAngleX / 2) * height / width) * 180.0 / Math.PI;
    }
}
