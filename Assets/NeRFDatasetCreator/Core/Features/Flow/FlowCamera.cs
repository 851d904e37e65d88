using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A pinhole camera as a dataset frame states it: camera-to-world in the output frame with OpenGL axes (+X right,
    /// +Y up, looking along −Z), focal lengths and principal point in pixels, image size. Continuous pixel coordinates put
    /// pixel (u, v)'s centre at (u + 0.5, v + 0.5), x to the right and y down the rows, the convention flow is given in.
    /// </summary>
    public sealed class FlowCamera
    {
        // Camera-to-world rotation (row-major) and centre.
        readonly double[] _r = new double[9];
        readonly double _cx, _cy, _cz;

        public FlowCamera(Matrix4x4d cameraToWorld, double fx, double fy, double cx, double cy, int width, int height)
        {
            if (!(fx > 0) || !(fy > 0)) throw new ArgumentException("Focal lengths must be positive.");
            if (width <= 0 || height <= 0) throw new ArgumentException("The image needs a positive size.");
            for (var row = 0; row < 3; row++)
                for (var column = 0; column < 3; column++) _r[3 * row + column] = cameraToWorld[row, column];
            _cx = cameraToWorld[0, 3];
            _cy = cameraToWorld[1, 3];
            _cz = cameraToWorld[2, 3];
            Fx = fx;
            Fy = fy;
            Cx = cx;
            Cy = cy;
            Width = width;
            Height = height;
        }

        public double Fx { get; }
        public double Fy { get; }
        public double Cx { get; }
        public double Cy { get; }
        public int Width { get; }
        public int Height { get; }

        public Vector3d Centre => new Vector3d(_cx, _cy, _cz);

        /// <summary>The world direction (not normalised; camera-space z = −1) of the ray through continuous pixel (x, y).</summary>
        public void Ray(double x, double y, out double dx, out double dy, out double dz)
        {
            double a = (x - Cx) / Fx, b = -(y - Cy) / Fy;
            dx = _r[0] * a + _r[1] * b - _r[2];
            dy = _r[3] * a + _r[4] * b - _r[5];
            dz = _r[6] * a + _r[7] * b - _r[8];
        }

        /// <summary>
        /// Projects the world point (px, py, pz) to continuous pixel coordinates; false when it is not in front of the camera
        /// (camera-space z ≥ 0). <paramref name="depth"/> is its z-distance in front of the camera.
        /// </summary>
        public bool Project(double px, double py, double pz, out double x, out double y, out double depth)
        {
            double qx = px - _cx, qy = py - _cy, qz = pz - _cz;
            // Camera space = Rᵀ·(p − c).
            double cx = _r[0] * qx + _r[3] * qy + _r[6] * qz;
            double cy = _r[1] * qx + _r[4] * qy + _r[7] * qz;
            double cz = _r[2] * qx + _r[5] * qy + _r[8] * qz;
            depth = -cz;
            if (!(depth > 0)) { x = y = double.NaN; return false; }
            x = Cx + Fx * cx / depth;
            y = Cy - Fy * cy / depth;
            return true;
        }

        /// <summary>Whether continuous pixel coordinates fall on the image ([0, W) × [0, H)).</summary>
        public bool Inside(double x, double y) => x >= 0 && y >= 0 && x < Width && y < Height;
    }
}
