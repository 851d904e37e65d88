using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which images truly see each point of the dataset's surface sample, decided from the captured depth maps
    /// (and masks): the ground truth a COLMAP track records. Point P (with unit normal n) is observed by an image when
    /// <list type="number">
    /// <item>it is in front of the camera (Z &gt; 0 in COLMAP's camera frame) and its projection (x, y) — COLMAP's PINHOLE
    /// formulas, or with a lens its distorted projection (the written OPENCV / OPENCV_FISHEYE camera's, <see cref="ColmapPose"/>),
    /// where the lens images that ray and no other (the pixel undistorts back to it) — has all four nearest pixel centres inside the image: the 2×2 block
    /// (⌊x − ½⌋ … +1, ⌊y − ½⌋ … +1), i.e. ½ ≤ x &lt; W − ½ and likewise y;</item>
    /// <item>it is not seen edge-on: |cos θ| ≥ <see cref="MinCosine"/>, θ between n and the viewing ray;</item>
    /// <item>at each of those four pixel centres the mask (when the dataset has masks) is 255 and the depth map holds a
    /// surface (0 = none, 65535 = clamped, both refused) whose depth d·q (q = 0.001 output units a step) agrees with
    /// the depth of P's tangent plane along that pixel's ray, z_plane = (n_c·P_c)/(n_c·r), r = ((u − cx)/fx, (v − cy)/fy, 1)
    /// (with a lens, r = (undistort((u − cx)/fx, (v − cy)/fy), 1): the ray the distorted pixel centre sees),
    /// within τ = q/2 + κ·Φ, Φ = Z/(min(fx, fy)·|cos θ|), κ = <see cref="FootprintFraction"/>.</item>
    /// </list>
    /// Why τ is that. Φ is the local pixel footprint: one pixel covers Z/f output units across the ray at depth Z and
    /// Z/(f·cos θ) along a surface tilted by θ, whose depth changes by at most that much within the pixel. The tangent
    /// plane removes the first-order part of the depth difference between P and the pixel centres, so what is left
    /// is: the 16-bit quantisation, ±q/2 (0.5 mm at scale 1: round(z·1000)); where the renderer sampled the pixel —
    /// at its centre for supersampling 1 and odd k; for even k the harmonic mean of the central samples, the centre's
    /// depth on a plane, and a sample up to √2/(2k) px off it across a step (pixels.md §4), at most 0.354·Φ·|sin θ| for k = 2; mesh faceting (interpolated normals differ from the face normal by a few degrees,
    /// tens of percent of Φ·tan Δ only at grazing angles, which the cosine limit removes) and curvature (Φ²/2R,
    /// 10⁻⁵ units for R = 1 at 800 px). κ = ½ covers these with margin and stays far below anything that hides a
    /// point: an occluder at least half a pixel's footprint in front of P (≈ 2 mm for a unit object 4 units away at
    /// 800 px) is seen. Requiring all four centres makes silhouettes safe: an occluding edge that is a straight line
    /// at the pixel scale and covers P's projection covers at least one corner of the square the four centres span,
    /// so a point just behind a silhouette is never listed; conversely, a visible point within about a pixel of a
    /// silhouette, of the image border or of a mask edge is left out of that image (conservative: missing
    /// observations, never wrong ones). Not seen at all: occluders thinner than a pixel between the sampled centres,
    /// and anything outside the target, which the depth pass does not render (output-format.md: depth holds only the
    /// target's geometry). A point without a normal (0, 0, 0) is given a plane facing the camera, which refuses it on
    /// surfaces steeper than τ allows.
    /// </summary>
    public static class ColmapVisibility
    {
        /// <summary>κ: the depth tolerance beyond quantisation, as a fraction of the local pixel footprint.</summary>
        public const double FootprintFraction = 0.5;

        /// <summary>Points seen more edge-on than this (|cos θ| &lt; 0.1, θ &gt; 84.3°) are not observations.</summary>
        public const double MinCosine = 0.1;

        /// <summary>The mask value of full target coverage; edge coverage (1–254) and background (0) refuse.</summary>
        public const byte Foreground = 255;

        /// <summary>Point positions and normals as flat arrays, built once and walked by every view in order.</summary>
        public sealed class PointArrays
        {
            public PointArrays(IReadOnlyList<CloudPoint> points)
            {
                Count = points.Count;
                X = new double[Count]; Y = new double[Count]; Z = new double[Count];
                NX = new double[Count]; NY = new double[Count]; NZ = new double[Count];
                for (var i = 0; i < Count; i++)
                {
                    var p = points[i];
                    X[i] = p.Position.X; Y[i] = p.Position.Y; Z[i] = p.Position.Z;
                    NX[i] = p.Normal.X; NY[i] = p.Normal.Y; NZ[i] = p.Normal.Z;
                }
            }

            public int Count { get; }
            internal readonly double[] X, Y, Z, NX, NY, NZ;
        }

        /// <summary>
        /// Per frame of <paramref name="scene"/> (which must have depth for every frame), the indices of the points
        /// it observes, ascending. Each depth map and mask is decoded once, then every point is projected into that view.
        /// </summary>
        public static int[][] Compute(ExportScene scene, IReadOnlyList<CloudPoint> points)
        {
            if (!scene.HasDepth) throw new ArgumentException("Visibility needs a depth map for every frame.", nameof(scene));
            var arrays = new PointArrays(points);
            var k = scene.Intrinsics;
            var masks = scene.HasMasks;
            var rays = scene.Lens != null ? new LensRays(k, scene.Lens) : null;
            var result = new int[scene.Frames.Count][];
            var visible = new List<int>();
            for (var v = 0; v < scene.Frames.Count; v++)
            {
                var frame = scene.Frames[v];
                var depth = ReadDepth(Path.Combine(scene.RootDirectory, frame.DepthPath), k);
                var mask = masks ? ReadMask(Path.Combine(scene.RootDirectory, frame.MaskPath), k) : null;
                Observe(ColmapPose.FromCameraToWorld(frame.CameraToWorld), k, depth, mask, scene.DepthUnitScale, arrays, visible, scene.Lens, rays);
                result[v] = visible.ToArray();
            }
            return result;
        }

        /// <summary>
        /// The points one view observes (indices ascending, into <paramref name="visible"/>, which is cleared first):
        /// <paramref name="depth"/> holds W×H steps of <paramref name="depthUnit"/> output units, top row first;
        /// <paramref name="mask"/> W×H bytes, or null to use depth alone.
        /// </summary>
        public static void Observe(ColmapPose pose, CameraIntrinsics k, ushort[] depth, byte[] mask, double depthUnit,
            PointArrays points, List<int> visible, LensDistortion lens = null, LensRays rays = null)
        {
            if (lens != null && rays == null) rays = new LensRays(k, lens);
            int width = k.Width, height = k.Height;
            if (depth == null || depth.Length != width * height) throw new ArgumentException("The depth map must hold W×H samples.", nameof(depth));
            if (mask != null && mask.Length != width * height) throw new ArgumentException("The mask must hold W×H samples.", nameof(mask));
            visible.Clear();
            double fx = k.FlX, fy = k.FlY, cx = k.Cx, cy = k.Cy;
            double footprintPerDepth = FootprintFraction / Math.Min(fx, fy), halfStep = depthUnit / 2;
            double r00 = pose.R00, r01 = pose.R01, r02 = pose.R02, r10 = pose.R10, r11 = pose.R11, r12 = pose.R12, r20 = pose.R20, r21 = pose.R21, r22 = pose.R22;
            double tx = pose.Translation.X, ty = pose.Translation.Y, tz = pose.Translation.Z;
            double[] xs = points.X, ys = points.Y, zs = points.Z, nxs = points.NX, nys = points.NY, nzs = points.NZ;
            for (var i = 0; i < points.Count; i++)
            {
                double px = xs[i], py = ys[i], pz = zs[i];
                var zc = r20 * px + r21 * py + r22 * pz + tz;
                if (!(zc > 0)) continue;
                var xc = r00 * px + r01 * py + r02 * pz + tx;
                var yc = r10 * px + r11 * py + r12 * pz + ty;
                // The same expressions as ColmapPose.Project, so the decision is about the very (x, y) written.
                double fu, fv;
                if (lens == null)
                {
                    fu = fx * xc / zc + cx - 0.5;
                    fv = fy * yc / zc + cy - 0.5;
                }
                else
                {
                    double xn = xc / zc, yn = yc / zc;
                    lens.Distort(xn, yn, out var xd, out var yd);
                    // Beyond where a lens's polynomial turns back, Distort folds a second ray onto an imaged pixel: the
                    // image there shows the ray the pixel undistorts to, not this one.
                    if (!lens.Undistort(xd, yd, out var ux, out var uy) || !(Math.Abs(ux - xn) + Math.Abs(uy - yn) <= 1e-6 * (1 + Math.Abs(xn) + Math.Abs(yn)))) continue;
                    fu = fx * xd + cx - 0.5;
                    fv = fy * yd + cy - 0.5;
                }
                if (!(fu >= 0 && fv >= 0)) continue;
                int i0 = (int)fu, j0 = (int)fv;
                if (i0 + 1 >= width || j0 + 1 >= height) continue;

                double nx = nxs[i], ny = nys[i], nz = nzs[i];
                var ncx = r00 * nx + r01 * ny + r02 * nz;
                var ncy = r10 * nx + r11 * ny + r12 * nz;
                var ncz = r20 * nx + r21 * ny + r22 * nz;
                var distance = Math.Sqrt(xc * xc + yc * yc + zc * zc);
                var normalLength = Math.Sqrt(ncx * ncx + ncy * ncy + ncz * ncz);
                double planeDot, cosine;
                if (normalLength > 0)
                {
                    planeDot = ncx * xc + ncy * yc + ncz * zc;
                    cosine = Math.Abs(planeDot) / (normalLength * distance);
                }
                else
                {
                    // No normal: the plane through P facing the camera.
                    ncx = -xc / distance; ncy = -yc / distance; ncz = -zc / distance;
                    planeDot = -distance;
                    cosine = 1;
                }
                if (!(cosine >= MinCosine)) continue;
                var tolerance = halfStep + zc * footprintPerDepth / cosine;

                var seen = true;
                for (var c = 0; c < 4 && seen; c++)
                {
                    int u = i0 + (c & 1), v = j0 + (c >> 1);
                    var at = v * width + u;
                    if (mask != null && mask[at] != Foreground) { seen = false; break; }
                    int steps = depth[at];
                    if (steps == 0 || steps == ushort.MaxValue) { seen = false; break; }
                    double rx, ry;
                    if (rays == null)
                    {
                        rx = (u + 0.5 - cx) / fx;
                        ry = (v + 0.5 - cy) / fy;
                    }
                    else
                    {
                        rx = rays.X[at];
                        ry = rays.Y[at];
                        if (double.IsNaN(rx)) { seen = false; break; }
                    }
                    var planeDepth = planeDot / (ncx * rx + ncy * ry + ncz);
                    if (!(Math.Abs(planeDepth - steps * depthUnit) <= tolerance)) seen = false;
                }
                if (seen) visible.Add(i);
            }
        }

        /// <summary>
        /// Through a lens, the ray each pixel centre sees: (x, y) with z = 1 in COLMAP's camera frame (y down), the
        /// undistorted normalised position of ((u + ½ − cx)/fx, (v + ½ − cy)/fy); NaN where the lens images no ray. Built
        /// once per export (one camera for every image), W×H of each.
        /// </summary>
        public sealed class LensRays
        {
            public LensRays(CameraIntrinsics k, LensDistortion lens)
            {
                int width = k.Width, height = k.Height;
                X = new double[width * height];
                Y = new double[width * height];
                for (var v = 0; v < height; v++)
                    for (var u = 0; u < width; u++)
                    {
                        var at = v * width + u;
                        if (lens.Undistort((u + 0.5 - k.Cx) / k.FlX, (v + 0.5 - k.Cy) / k.FlY, out var x, out var y)) { X[at] = x; Y[at] = y; }
                        else X[at] = Y[at] = double.NaN;
                    }
            }

            internal readonly double[] X, Y;
        }

        static ushort[] ReadDepth(string path, CameraIntrinsics k)
        {
            var depth = PngGray16Reader.Read(path, out var width, out var height);
            if (width != k.Width || height != k.Height) throw SizeProblem("depth", path, width, height, k);
            return depth;
        }

        static byte[] ReadMask(string path, CameraIntrinsics k)
        {
            PngImage image;
            try { image = PngReader.Read(path); }
            catch (InvalidDataException e)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem("mask", path, e.Message.StartsWith(path) ? e.Message.Substring(path.Length).TrimStart() : e.Message, "Re-capture the mask with this plugin (8-bit grey PNG).") });
            }
            if (image.BitDepth != 8 || image.ColorType != PngInfo.ColorTypeGray)
                throw new InvalidParameterException(new[] { new ValidationProblem("mask", path, "is not an 8-bit greyscale PNG (the mask layout).", "Re-capture the mask with this plugin (8-bit grey PNG).") });
            if (image.Width != k.Width || image.Height != k.Height) throw SizeProblem("mask", path, image.Width, image.Height, k);
            return image.Samples;
        }

        static InvalidParameterException SizeProblem(string field, string path, int width, int height, CameraIntrinsics k) =>
            new InvalidParameterException(new[]
            {
                new ValidationProblem(field, path, "is " + width + "×" + height + " but the images are " + k.Width + "×" + k.Height + ", so it cannot tell which points the image sees.",
                    "Re-capture the " + field + " maps at the image size (or convert without them)."),
            });
    }
}
