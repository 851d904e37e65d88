namespace NerfDatasetCreator
{
    /// <summary>
    /// One image's <c>cam_from_world</c> as COLMAP stores it (unit quaternion QW QX QY QZ, translation TX TY TZ, OpenCV
    /// camera axes) and its projection with COLMAP's PINHOLE model: X_cam = R·X + t, then x = fx·X/Z + cx,
    /// y = fy·Y/Z + cy (colmap src/colmap/sensor/models.h, <c>PinholeCameraModel::ImgFromCam</c>), in COLMAP's pixel
    /// convention — the image's top-left corner at (0, 0), the centre of the top-left pixel at (0.5, 0.5)
    /// (doc/cameras.rst line 51), the same as <see cref="CameraIntrinsics"/>. R is the quaternion's matrix as Eigen
    /// builds it (<c>Quaterniond::toRotationMatrix</c>), so the 2D points written are the points COLMAP, pycolmap and
    /// gsplat compute from the written quaternion.
    /// </summary>
    public readonly struct ColmapPose
    {
        public ColmapPose(Quaterniond rotation, Vector3d translation)
        {
            Rotation = rotation;
            Translation = translation;
            double w = rotation.W, x = rotation.X, y = rotation.Y, z = rotation.Z;
            R00 = 1 - 2 * (y * y + z * z); R01 = 2 * (x * y - w * z); R02 = 2 * (x * z + w * y);
            R10 = 2 * (x * y + w * z); R11 = 1 - 2 * (x * x + z * z); R12 = 2 * (y * z - w * x);
            R20 = 2 * (x * z - w * y); R21 = 2 * (y * z + w * x); R22 = 1 - 2 * (x * x + y * y);
        }

        /// <summary>The pose COLMAP's files hold for an OpenGL camera-to-world matrix (<see cref="ColmapTextWriter.WorldToCamera"/>).</summary>
        public static ColmapPose FromCameraToWorld(Matrix4x4d cameraToWorldOpenGl)
        {
            ColmapTextWriter.WorldToCamera(cameraToWorldOpenGl, out var q, out var t);
            return new ColmapPose(q, t);
        }

        public Quaterniond Rotation { get; }
        public Vector3d Translation { get; }

        /// <summary>Rows of the world-to-camera rotation.</summary>
        public readonly double R00, R01, R02, R10, R11, R12, R20, R21, R22;

        /// <summary>A world point in COLMAP's camera frame (x right, y down, z forward).</summary>
        public Vector3d ToCamera(Vector3d p) => new Vector3d(
            R00 * p.X + R01 * p.Y + R02 * p.Z + Translation.X,
            R10 * p.X + R11 * p.Y + R12 * p.Z + Translation.Y,
            R20 * p.X + R21 * p.Y + R22 * p.Z + Translation.Z);

        /// <summary>The pixel position of world point <paramref name="p"/> (meaningful only in front of the camera, Z &gt; 0).</summary>
        public void Project(Vector3d p, CameraIntrinsics k, out double x, out double y)
        {
            var c = ToCamera(p);
            x = k.FlX * c.X / c.Z + k.Cx;
            y = k.FlY * c.Y / c.Z + k.Cy;
        }

        /// <summary>
        /// The pixel position of <paramref name="p"/> through <paramref name="lens"/> (null: the pinhole above, same
        /// expression): COLMAP's ImgFromCam for the written OPENCV / FULL_OPENCV / OPENCV_FISHEYE camera — (X/Z, Y/Z)
        /// distorted (<see cref="LensDistortion.Distort"/>, models.h's formulas, checked against them in
        /// ConvertLensTests), then f·x + c.
        /// </summary>
        public void Project(Vector3d p, CameraIntrinsics k, LensDistortion lens, out double x, out double y)
        {
            if (lens == null)
            {
                Project(p, k, out x, out y);
                return;
            }
            var c = ToCamera(p);
            lens.Distort(c.X / c.Z, c.Y / c.Z, out var xd, out var yd);
            x = k.FlX * xd + k.Cx;
            y = k.FlY * yd + k.Cy;
        }
    }
}
