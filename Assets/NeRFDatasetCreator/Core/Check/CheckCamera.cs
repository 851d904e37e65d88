using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A view's pinhole camera as the loaders read it: f = 0.5·W / tan(0.5·camera_angle_x) for both axes (square
    /// pixels), principal point (cx, cy) in continuous pixels (top-left corner at 0, rows down), and the OpenGL camera
    /// of <c>transform_matrix</c> (+X right, +Y up, looking along −Z). Pixel (u, v)'s centre is (u + ½, v + ½)
    /// (conventions.md, Intrinsics). The matrix is held as plain doubles: these run per pixel. With a
    /// <see cref="Lens"/> (the transforms files' <c>camera_model</c> and k1…p2, <see cref="TransformsLens"/>), pixels
    /// and rays go through it exactly as the loaders do: pixel → normalised (x_d, y_d) with y down → undistort → ray;
    /// and a point → (x, y) → distort → pixel.
    /// </summary>
    public sealed class CheckCamera
    {
        // Camera-to-world rotation (row-major) and centre.
        readonly double r00, r01, r02, r10, r11, r12, r20, r21, r22, tx, ty, tz;

        public CheckCamera(Matrix4x4d cameraToWorld, int width, int height, double focal, double cx, double cy, LensDistortion lens = null)
        {
            Lens = lens;
            Width = width;
            Height = height;
            Focal = focal;
            Cx = cx;
            Cy = cy;
            r00 = cameraToWorld[0, 0]; r01 = cameraToWorld[0, 1]; r02 = cameraToWorld[0, 2]; tx = cameraToWorld[0, 3];
            r10 = cameraToWorld[1, 0]; r11 = cameraToWorld[1, 1]; r12 = cameraToWorld[1, 2]; ty = cameraToWorld[1, 3];
            r20 = cameraToWorld[2, 0]; r21 = cameraToWorld[2, 1]; r22 = cameraToWorld[2, 2]; tz = cameraToWorld[2, 3];
        }

        /// <summary>The same camera (size, intrinsics, lens) at another pose: a moment within a shutter interval.</summary>
        public CheckCamera At(Matrix4x4d cameraToWorld) => new CheckCamera(cameraToWorld, Width, Height, Focal, Cx, Cy, Lens);

        public int Width { get; }
        public int Height { get; }
        public double Focal { get; }
        public double Cx { get; }
        public double Cy { get; }

        /// <summary>The lens the images were taken through, or null for a pinhole.</summary>
        public LensDistortion Lens { get; }

        /// <summary>The viewing direction in the world (the camera's −Z).</summary>
        public Vector3d Forward => new Vector3d(-r02, -r12, -r22);

        /// <summary>
        /// The world point on pixel (<paramref name="u"/>, <paramref name="v"/>) (continuous coordinates) at z-depth
        /// <paramref name="z"/>. False (and a point on the undistorted guess) where the lens images no ray.
        /// </summary>
        public bool BackProject(double u, double v, double z, out double x, out double y, out double w)
        {
            var ok = CameraPoint(u, v, z, out var cxr, out var cyr, out var czr);
            x = r00 * cxr + r01 * cyr + r02 * czr + tx;
            y = r10 * cxr + r11 * cyr + r12 * czr + ty;
            w = r20 * cxr + r21 * cyr + r22 * czr + tz;
            return ok;
        }

        /// <summary>
        /// The camera-frame (OpenGL: y up, looking along −z) point on pixel (<paramref name="u"/>, <paramref name="v"/>)
        /// at z-depth <paramref name="z"/>, through the lens when there is one.
        /// </summary>
        public bool CameraPoint(double u, double v, double z, out double x, out double y, out double w)
        {
            double nx = (u - Cx) / Focal, ny = (v - Cy) / Focal; // OpenCV normalised, y down
            var ok = true;
            if (Lens != null) ok = Lens.Undistort(nx, ny, out nx, out ny);
            x = nx * z;
            y = -ny * z;
            w = -z;
            return ok;
        }

        /// <summary>
        /// Projects a world point: continuous pixel coordinates and its z-depth (positive in front). False when the point
        /// is not in front of the camera.
        /// </summary>
        public bool Project(double x, double y, double w, out double u, out double v, out double z)
        {
            double dx = x - tx, dy = y - ty, dz = w - tz;
            // Camera coordinates: Rᵀ·(p − t).
            double px = r00 * dx + r10 * dy + r20 * dz;
            double py = r01 * dx + r11 * dy + r21 * dz;
            double pz = r02 * dx + r12 * dy + r22 * dz;
            z = -pz;
            if (!(z > 0))
            {
                u = v = 0;
                return false;
            }
            double nx = px / z, ny = -py / z; // OpenCV normalised, y down
            if (Lens != null)
            {
                // Only the unfolded part of the lens images a point (as LensDistortion.Undistort accepts it): beyond it the
                // polynomial turns back and would put a point outside the view into the frame.
                Lens.Jacobian(nx, ny, out var a, out var b, out var c, out var d);
                if (!(a * d - b * c > 0 && a + d > 0)) { u = v = 0; return false; }
                Lens.Distort(nx, ny, out nx, out ny);
            }
            u = Focal * nx + Cx;
            v = Focal * ny + Cy;
            return true;
        }

        /// <summary>A camera-frame direction turned into the world frame.</summary>
        public void ToWorld(double x, double y, double z, out double wx, out double wy, out double wz)
        {
            wx = r00 * x + r01 * y + r02 * z;
            wy = r10 * x + r11 * y + r12 * z;
            wz = r20 * x + r21 * y + r22 * z;
        }

        public static double FocalOf(int width, double cameraAngleX) => 0.5 * width / Math.Tan(0.5 * cameraAngleX);
    }
}
