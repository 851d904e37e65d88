using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One camera read from an existing dataset: its name there, the camera-to-world matrix exactly as the file
    /// holds it (Blender world, OpenGL camera axes, after the file's own normalisation), the Unity pose that
    /// reproduces it, and its pinhole intrinsics when the file gives the image size.
    /// </summary>
    [Serializable]
    public sealed class ImportedCamera
    {
        public ImportedCamera(string name, string split, Matrix4x4d fileCameraToWorld, UnityPose pose, ImportedIntrinsics intrinsics)
        {
            Name = name ?? "";
            Split = split;
            FileCameraToWorld = fileCameraToWorld;
            Pose = pose;
            Intrinsics = intrinsics;
        }

        /// <summary><c>file_path</c> of a transforms file, <c>NAME</c> of a COLMAP image.</summary>
        public string Name { get; }

        /// <summary>The split the file puts the camera in (<c>train</c>, <c>val</c>, <c>test</c>), or null when it does not say.</summary>
        public string Split { get; }

        /// <summary>The output camera-to-world matrix as read (OpenGL camera axes; COLMAP poses converted to them).</summary>
        public Matrix4x4d FileCameraToWorld { get; }

        /// <summary>Where a Unity camera goes so that its written matrix is <see cref="FileCameraToWorld"/>.</summary>
        public UnityPose Pose { get; }

        public ImportedIntrinsics Intrinsics { get; }
    }

    /// <summary>
    /// Pinhole intrinsics as a file gives them: focal lengths and principal point in pixels (top-left image corner
    /// at 0), and the image size, which Blender-format files leave to the PNGs (then <see cref="HasSize"/> is false
    /// and only <see cref="CameraAngleX"/> is known).
    /// </summary>
    [Serializable]
    public sealed class ImportedIntrinsics
    {
        public ImportedIntrinsics(double cameraAngleX, int width, int height, double flX, double flY, double cx, double cy)
        {
            CameraAngleX = cameraAngleX;
            Width = width;
            Height = height;
            FlX = flX;
            FlY = flY;
            Cx = cx;
            Cy = cy;
        }

        /// <summary>Only a horizontal field of view (nerf_synthetic's files): no size, no principal point.</summary>
        public static ImportedIntrinsics AngleOnly(double cameraAngleX) => new ImportedIntrinsics(cameraAngleX, 0, 0, 0, 0, 0, 0);

        /// <summary>Horizontal field of view in radians.</summary>
        public double CameraAngleX { get; }

        public int Width { get; }
        public int Height { get; }
        public double FlX { get; }
        public double FlY { get; }
        public double Cx { get; }
        public double Cy { get; }

        public bool HasSize => Width > 0 && Height > 0;

        /// <summary>Unity's <c>Camera.fieldOfView</c> (vertical, degrees) for this camera, with <paramref name="width"/>×<paramref name="height"/> when the file gives no size.</summary>
        public double VerticalFovDegrees(int width, int height) =>
            HasSize
                ? 2 * Math.Atan(0.5 * Height / FlY) * 180 / Math.PI
                : CameraIntrinsics.VerticalFovDegreesFromHorizontal(CameraAngleX, width, height);

        /// <summary>Equal within a relative 1e-9 (files written in float32 by one tool agree exactly).</summary>
        public bool SameAs(ImportedIntrinsics other) =>
            other != null && Width == other.Width && Height == other.Height && Close(CameraAngleX, other.CameraAngleX) &&
            Close(FlX, other.FlX) && Close(FlY, other.FlY) && Close(Cx, other.Cx) && Close(Cy, other.Cy);

        static bool Close(double a, double b) => Math.Abs(a - b) <= 1e-9 * Math.Max(1, Math.Max(Math.Abs(a), Math.Abs(b)));
    }
}
