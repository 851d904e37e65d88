using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>depth vs normals</b>: on smooth surfaces, the normal computed from the depth map — the surface points of the
    /// pixels b to the left, right, above and below, back-projected with the intrinsics, crossed, and turned into the
    /// world with the pose — agrees with the normal image (output world frame). Normals in the camera frame, flipped,
    /// or depth along the ray (which bends planes) give large angles.
    /// </summary>
    public sealed class DepthNormalsCheck : IViewCheck
    {
        /// <summary>
        /// Largest median angle per view. 8-bit normals are good to ~0.5°; depth steps (1/1000 of an output unit) over the
        /// baseline below add up to ~2°. A normal image in the camera frame is off by the camera's rotation (tens of
        /// degrees); depth along the ray tilts a surface by its angle off the optical axis.
        /// </summary>
        public const double MaxMedianDegrees = 5;

        /// <summary>The baseline is chosen so that the surface moves by at least this many depth steps across it (quantisation noise ≤ ~3°).</summary>
        const double BaselineSteps = 20;
        const int MaxBaseline = 8;

        /// <summary>Neighbouring normals closer than this (cos 15°) mark a smooth surface; creases and silhouettes are left out.</summary>
        const double SmoothCosine = 0.966;

        /// <summary>A view needs this many smooth samples to be judged; fewer (a tiny or crease-only target) are not held against it.</summary>
        const int MinSamples = 50;

        /// <summary>Samples per view at most (a grid stride keeps the cost down on large images).</summary>
        const int MaxSamplesPerView = 20000;

        public string Name => "depth vs normals";

        int _views, _judged, _bad;
        readonly List<double> _medians = new List<double>();
        double _worst;

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            var depth = images.Depth;
            var normals = images.Normals;
            var camera = view.Camera;
            if (depth == null || normals == null || camera == null) return;
            _views++;
            int w = images.Width, h = images.Height;
            var scale = view.DepthScale;
            var b = Baseline(depth, camera.Focal);
            var stride = Math.Max(1, (int)Math.Sqrt((double)w * h / MaxSamplesPerView));
            var angles = new List<double>();
            for (var v = b; v < h - b; v += stride)
                for (var u = b; u < w - b; u += stride)
                {
                    var i = v * w + u;
                    int z0 = depth[i], zl = depth[i - b], zr = depth[i + b], zu = depth[i - b * w], zd = depth[i + b * w];
                    if (z0 == 0 || zl == 0 || zr == 0 || zu == 0 || zd == 0) continue;
                    if (!Even(zl, z0, zr) || !Even(zu, z0, zd)) continue;
                    if (!Normal(normals, i, out var nx, out var ny, out var nz)) continue;
                    if (!Near(normals, i - b, nx, ny, nz) || !Near(normals, i + b, nx, ny, nz) || !Near(normals, i - b * w, nx, ny, nz) || !Near(normals, i + b * w, nx, ny, nz)) continue;
                    // Camera-frame points of the four neighbours (OpenGL camera: y up, rows down, looking along −z).
                    Point(camera, u - b, v, zl * scale, out var lx, out var ly, out var lz);
                    Point(camera, u + b, v, zr * scale, out var rx, out var ry, out var rz);
                    Point(camera, u, v - b, zu * scale, out var ux, out var uy, out var uz);
                    Point(camera, u, v + b, zd * scale, out var dx, out var dy, out var dz);
                    double ax = rx - lx, ay = ry - ly, az = rz - lz, bx = dx - ux, by = dy - uy, bz = dz - uz;
                    double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
                    // Towards the camera: the centre point p has n·p < 0.
                    Point(camera, u, v, z0 * scale, out var px, out var py, out var pz);
                    if (cx * px + cy * py + cz * pz > 0) { cx = -cx; cy = -cy; cz = -cz; }
                    var length = Math.Sqrt(cx * cx + cy * cy + cz * cz);
                    if (!(length > 0)) continue;
                    camera.ToWorld(cx / length, cy / length, cz / length, out var wx, out var wy, out var wz);
                    var dot = Math.Max(-1, Math.Min(1, wx * nx + wy * ny + wz * nz));
                    angles.Add(Math.Acos(dot));
                }
            if (angles.Count < MinSamples) return;
            _judged++;
            var median = CheckFigures.Median(angles);
            _medians.Add(median);
            if (median > _worst) _worst = median;
            if (median * 180 / Math.PI > MaxMedianDegrees)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.NormalFile, view.Frame, "the normals differ from the depth's by a median " + CheckFigures.Degrees(median) +
                    " over " + angles.Count + " smooth-surface samples, above " + DatasetCheckResult.Number(MaxMedianDegrees) + "°: normals in the camera (or Unity) frame, flipped, or depth along the ray instead of z."));
            }
        }

        /// <summary>Pixels between the points crossed: enough that the surface moves ≥ 20 depth steps at the median depth (1 … 8).</summary>
        static int Baseline(ushort[] depth, double focal)
        {
            var samples = new List<double>();
            var step = Math.Max(1, depth.Length / 4096);
            for (var i = 0; i < depth.Length; i += step)
                if (depth[i] != 0) samples.Add(depth[i]);
            if (samples.Count == 0) return 1;
            // A pixel spans z / f in the plane at depth z, in depth steps too.
            var spacing = CheckFigures.Median(samples) / focal;
            return Math.Max(1, Math.Min(MaxBaseline, (int)Math.Ceiling(BaselineSteps / Math.Max(spacing, 1e-9))));
        }

        /// <summary>The two one-sided differences agree within 3× and 3 steps: no depth edge between the three samples.</summary>
        static bool Even(int a, int b, int c)
        {
            int d1 = Math.Abs(b - a), d2 = Math.Abs(c - b);
            return Math.Max(d1, d2) <= 3 * Math.Min(d1, d2) + 3;
        }

        // The pixel's ray through the written lens (CheckCamera.CameraPoint): with a distorted lens, a pinhole ray would bend planes.
        static void Point(CheckCamera camera, double u, double v, double z, out double x, out double y, out double w) =>
            camera.CameraPoint(u + 0.5, v + 0.5, z, out x, out y, out w);

        static bool Normal(byte[] rgb, int i, out double x, out double y, out double z)
        {
            int r = rgb[3 * i], g = rgb[3 * i + 1], b = rgb[3 * i + 2];
            x = y = z = 0;
            if ((r | g | b) == 0) return false;
            x = r / 127.5 - 1;
            y = g / 127.5 - 1;
            z = b / 127.5 - 1;
            var length = Math.Sqrt(x * x + y * y + z * z);
            if (!(length > 0.5)) return false;
            x /= length;
            y /= length;
            z /= length;
            return true;
        }

        static bool Near(byte[] rgb, int i, double x, double y, double z) =>
            Normal(rgb, i, out var a, out var b, out var c) && a * x + b * y + c * z >= SmoothCosine;

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no view has both a depth PNG and a normal PNG");
            if (_judged == 0) return DatasetCheckResult.Skip(Name, "no view has " + MinSamples + " samples on smooth surfaces");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _judged + " views, median angle " + CheckFigures.Degrees(CheckFigures.Median(_medians)) + ", worst view " + CheckFigures.Degrees(_worst),
                "median ≤ " + DatasetCheckResult.Number(MaxMedianDegrees) + "° per view", _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
