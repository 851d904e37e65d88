using System;

namespace NerfDatasetCreator
{
    /// <summary>The capture camera: Unity's vertical field of view and clip planes, or a scene camera to copy them from.</summary>
    [Serializable]
    public sealed class CameraSettings
    {
        /// <summary>
        /// nerf_synthetic's field of view: its <c>camera_angle_x</c> 0.6911112070083618 rad (a 50 mm lens on a 36 mm
        /// sensor, 2·atan(36/100) rounded to float) as a vertical angle in degrees — square images have equal angles.
        /// </summary>
        public static readonly double NerfSyntheticVerticalFovDegrees = 0.6911112070083618 * 180.0 / Math.PI;

        /// <summary>Unity's <c>Camera.fieldOfView</c>: the vertical field of view in degrees.</summary>
        public double VerticalFovDegrees = NerfSyntheticVerticalFovDegrees;

        public double NearClip = 0.1;
        public double FarClip = 100;

        /// <summary>
        /// Name or hierarchy path of a scene camera whose field of view, clip planes and culling are copied at
        /// capture time; empty to use the values above. The Unity side resolves it.
        /// </summary>
        public string CopyFromCamera = "";

        public CameraSettings Clone() => (CameraSettings)MemberwiseClone();
    }
}
