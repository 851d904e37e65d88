using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>How a physical camera's sensor gate is fitted to the image: the values of Unity's Camera.GateFitMode.</summary>
    public enum GateFit
    {
        None = 0,
        Vertical = 1,
        Horizontal = 2,
        Fill = 3,
        Overscan = 4,
    }

    /// <summary>
    /// The vertical field of view with which a physical template camera (focal length, sensor size, gate fit) frames a
    /// W × H image, so that the capture's plain pinhole camera reproduces its framing. A physical camera's own
    /// <c>Camera.fieldOfView</c> is the sensor height's angle, 2·atan(h / 2f), i.e. the Vertical fit; the gate fit then
    /// decides which sensor side spans the image (Unity Manual, "Physical Cameras"; Scripting API Camera.GateFitMode):
    /// <list type="bullet">
    /// <item>Vertical: the sensor height spans the image height: v = 2·atan(h / 2f).</item>
    /// <item>Horizontal: the sensor width spans the image width: tan(v/2) = tan(hfov/2) / a = w / (2f·a), a = W/H.</item>
    /// <item>Fill: the sensor covers the whole image, cropped on one side: Horizontal when the image is wider than the
    /// sensor (a &gt; w/h), else Vertical — the smaller of the two angles.</item>
    /// <item>Overscan: the whole sensor is visible, with more around it: Vertical when the image is wider than the
    /// sensor, else Horizontal — the larger of the two.</item>
    /// <item>None stretches the sensor to the image: non-square pixels unless the aspects match, which a pinhole
    /// dataset (one focal length for x and y) cannot describe — refused unless they do (within 0.1 %, or within what
    /// whole pixels allow at the image's size: less than half a pixel of stretch on either side).</item>
    /// </list>
    /// Cinemachine 3's CinemachineDebug.GetCameraRect makes the same Fill/Overscan choice. Lens shift moves the
    /// principal point off the image centre, which the datasets' intrinsics (c = size / 2) cannot describe: refused.
    /// </summary>
    public static class PhysicalCameraFraming
    {
        /// <summary>Relative difference of image and sensor aspect under which gate fit None counts as no stretch.</summary>
        public const double AspectTolerance = 1e-3;

        /// <summary>
        /// How far a W × H image's aspect can be from the one it approximates only because its sides are whole pixels: the
        /// largest relative change of W/H when each side moves by half a pixel, (1 + 1/2W) / (1 − 1/2H) − 1. A 160 × 91
        /// image (the preflight's calibration of a 1000 × 567 capture) is 0.87 %; a 1920 × 1080 image 0.07 %.
        /// </summary>
        public static double RoundingTolerance(int width, int height) =>
            width <= 0 || height <= 0 ? 0 : (1 + 0.5 / width) / (1 - 0.5 / height) - 1;

        /// <summary>
        /// The vertical field of view in degrees for a W × H image; gate fit None is accepted within
        /// <see cref="AspectTolerance"/> or, for small images, within <see cref="RoundingTolerance"/> of the sensor's aspect
        /// (review R4-5: the preflight's 160-px calibration of an accepted capture rounds its aspect by up to ~0.9 %).
        /// Throws <see cref="InvalidParameterException"/> for a framing a pinhole cannot reproduce.
        /// </summary>
        public static double VerticalFovDegrees(double focalLengthMm, double sensorWidthMm, double sensorHeightMm, double lensShiftX,
            double lensShiftY, GateFit fit, int width, int height, string field = "camera.copyFromCamera")
        {
            InvalidParameterException.ThrowIfAny(Problem(focalLengthMm, sensorWidthMm, sensorHeightMm, lensShiftX, lensShiftY, fit, width, height, field));
            return Fov(focalLengthMm, sensorWidthMm, sensorHeightMm, fit, (double)width / height);
        }

        /// <summary>Why this framing of a W × H image cannot be reproduced by the capture's pinhole camera, or null (see <see cref="VerticalFovDegrees(double, double, double, double, double, GateFit, int, int, string)"/>).</summary>
        public static ValidationProblem Problem(double focalLengthMm, double sensorWidthMm, double sensorHeightMm, double lensShiftX,
            double lensShiftY, GateFit fit, int width, int height, string field = "camera.copyFromCamera") =>
            Problem(focalLengthMm, sensorWidthMm, sensorHeightMm, lensShiftX, lensShiftY, fit, height > 0 ? (double)width / height : 0,
                Math.Max(AspectTolerance, RoundingTolerance(width, height)), field);

        /// <summary>The vertical field of view in degrees at an exact image aspect; throws <see cref="InvalidParameterException"/> for a framing a pinhole cannot reproduce.</summary>
        public static double VerticalFovDegrees(double focalLengthMm, double sensorWidthMm, double sensorHeightMm, double lensShiftX,
            double lensShiftY, GateFit fit, double imageAspect, string field = "camera.copyFromCamera")
        {
            InvalidParameterException.ThrowIfAny(Problem(focalLengthMm, sensorWidthMm, sensorHeightMm, lensShiftX, lensShiftY, fit, imageAspect, field));
            return Fov(focalLengthMm, sensorWidthMm, sensorHeightMm, fit, imageAspect);
        }

        static double Fov(double focalLengthMm, double sensorWidthMm, double sensorHeightMm, GateFit fit, double imageAspect)
        {
            var vertical = 2 * Math.Atan(sensorHeightMm / (2 * focalLengthMm));
            var horizontalFit = 2 * Math.Atan(sensorWidthMm / (2 * focalLengthMm * imageAspect));
            var imageWiderThanSensor = imageAspect > sensorWidthMm / sensorHeightMm;
            double radians;
            switch (fit)
            {
                case GateFit.Horizontal: radians = horizontalFit; break;
                case GateFit.Fill: radians = imageWiderThanSensor ? horizontalFit : vertical; break;
                case GateFit.Overscan: radians = imageWiderThanSensor ? vertical : horizontalFit; break;
                default: radians = vertical; break; // Vertical, and None with matching aspects
            }
            return radians * 180 / Math.PI;
        }

        /// <summary>Why this framing at an exact image aspect cannot be reproduced by the capture's pinhole camera, or null.</summary>
        public static ValidationProblem Problem(double focalLengthMm, double sensorWidthMm, double sensorHeightMm, double lensShiftX,
            double lensShiftY, GateFit fit, double imageAspect, string field = "camera.copyFromCamera") =>
            Problem(focalLengthMm, sensorWidthMm, sensorHeightMm, lensShiftX, lensShiftY, fit, imageAspect, AspectTolerance, field);

        static ValidationProblem Problem(double focalLengthMm, double sensorWidthMm, double sensorHeightMm, double lensShiftX,
            double lensShiftY, GateFit fit, double imageAspect, double aspectTolerance, string field)
        {
            var ci = CultureInfo.InvariantCulture;
            if (!(focalLengthMm > 0) || !(sensorWidthMm > 0) || !(sensorHeightMm > 0) || !(imageAspect > 0) ||
                double.IsInfinity(focalLengthMm) || double.IsInfinity(sensorWidthMm) || double.IsInfinity(sensorHeightMm))
                return new ValidationProblem(field, string.Format(ci, "focal length {0} mm, sensor {1} × {2} mm", focalLengthMm, sensorWidthMm, sensorHeightMm),
                    "is a physical camera without a positive focal length and sensor size.", "Give the camera's lens a focal length and sensor size, or turn Physical Camera off.");
            if (Math.Abs(lensShiftX) > 1e-6 || Math.Abs(lensShiftY) > 1e-6)
                return new ValidationProblem(field, string.Format(ci, "lens shift ({0}, {1})", lensShiftX, lensShiftY),
                    "shifts the lens: the image centre is no longer the optical centre, which the dataset's intrinsics (cx = w/2, cy = h/2) assume.",
                    "Set the template camera's Lens Shift to 0, or pick another camera.");
            if (!Enum.IsDefined(typeof(GateFit), fit))
                return new ValidationProblem(field, "gate fit " + (int)fit, "has a gate fit this plugin does not know.", "Use Vertical, Horizontal, Fill or Overscan.");
            var sensorAspect = sensorWidthMm / sensorHeightMm;
            if (fit == GateFit.None && Math.Abs(imageAspect - sensorAspect) > aspectTolerance * sensorAspect)
                return new ValidationProblem(field, string.Format(ci, "gate fit None, sensor aspect {0:0.###}, image aspect {1:0.###}", sensorAspect, imageAspect),
                    "stretches the sensor to the image (gate fit None), so pixels are not square; the dataset's one focal length cannot describe that.",
                    "Set the template camera's Gate Fit to Vertical, Horizontal, Fill or Overscan, or make the image's aspect match the sensor's.");
            return null;
        }
    }
}
