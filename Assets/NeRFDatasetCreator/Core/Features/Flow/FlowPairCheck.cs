using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The flow check's four measurements of one frame pair a → b (<see cref="FlowCheck"/>, Documentation~/maintainers/check.md
    /// "flow"). Each returns how many pixels it judged and how many disagreed; the check turns them into shares and problems.
    /// </summary>
    public static class FlowPairCheck
    {
        /// <summary>Pixels of flow within this of the image border count as either inside or outside (the flow is float32: ~1e-4 px at 800 px).</summary>
        public const double BorderEpsilon = 1e-3;

        /// <summary>
        /// Pixels beyond what the depth's uncertainty allows: float32 flow and coordinates (~1e-4 px), plus the float32
        /// scene flow added to a point (~1e-7 relative, far below a pixel).
        /// </summary>
        public const double FlowSlackPixels = 0.02;

        /// <summary>
        /// |F(p) + B(p + F(p))| allowed besides <see cref="InverseSpreadShare"/> of B's local spread, pixels: float32 flow and
        /// coordinates (~1e-4 px) and the kink where the piecewise-flat mesh's flow bends at a facet edge.
        /// </summary>
        public const double InversePixels = 0.1;

        /// <summary>
        /// Bilinear interpolation of a smooth field errs by at most h²/8·(|B_xx| + |B_yy|) over a pixel (h = 1); where B's
        /// gradient changes across the cell by no more than B itself varies over its four pixels (the spread s), that is
        /// ≤ s/4. A small, fast-turning target (the analytic sphere, 20 px across, moving 10 px a step) varies by 3 px per
        /// pixel and errs by up to 0.35 px; a sign flip or an axis swap misses by twice the flow, far beyond.
        /// </summary>
        public const double InverseSpreadShare = 0.25;

        /// <summary>Depth difference allowed between a visible point and b's depth, relative (bilinear depth across a pixel on a slope, facets), at least the depths' uncertainties.</summary>
        public const double OcclusionRelative = 0.01;

        public struct Counts
        {
            public int Judged, Bad;
            public double Worst;
            public double Share => Judged == 0 ? 0 : (double)Bad / Judged;
        }

        /// <summary>
        /// (d) on every pixel: masks 0 or 255 and never both; NaN flow exactly where there is no surface (both masks 0, and
        /// no target in the scene flow's A) or the point is behind b's camera (outside 255); finite flow marked outside
        /// exactly when p + flow leaves b's image; A = 1 exactly where the pixel has flow or lies behind b's camera. Each
        /// sentence names what disagrees and how many pixels.
        /// </summary>
        public static List<(string file, string message)> Structure(FlowPairFiles f, FlowPair pair, int width, int height)
        {
            int notBinary = 0, both = 0, nanOccluded = 0, outsideWrong = 0, alphaWrong = 0;
            for (var v = 0; v < height; v++)
                for (var u = 0; u < width; u++)
                {
                    var p = v * width + u;
                    byte occ = f.Occluded[p], outs = f.Outside[p];
                    if ((occ != 0 && occ != 255) || (outs != 0 && outs != 255)) { notBinary++; continue; }
                    if (occ == 255 && outs == 255) both++;
                    float dx = f.Flow[2 * p], dy = f.Flow[2 * p + 1];
                    var finite = !float.IsNaN(dx) && !float.IsNaN(dy) && !float.IsInfinity(dx) && !float.IsInfinity(dy);
                    if (!finite)
                    {
                        if (occ == 255) nanOccluded++;
                    }
                    else
                    {
                        double x = u + 0.5 + dx, y = v + 0.5 + dy;
                        var nearBorder = Math.Abs(x) < BorderEpsilon || Math.Abs(y) < BorderEpsilon || Math.Abs(x - width) < BorderEpsilon || Math.Abs(y - height) < BorderEpsilon;
                        var inside = x >= 0 && y >= 0 && x < width && y < height;
                        if (!nearBorder && inside == (outs == 255)) outsideWrong++;
                    }
                    if (f.OnTarget != null && f.OnTarget[p] != (finite || outs == 255)) alphaWrong++;
                }
            var problems = new List<(string, string)>();
            if (notBinary > 0) problems.Add((pair.OccludedFile, notBinary + " pixels of the occluded or outside mask (" + System.IO.Path.GetFileName(pair.OutsideFile) + ") are neither 0 nor 255."));
            if (both > 0) problems.Add((pair.OccludedFile, both + " pixels are marked both occluded and outside (" + System.IO.Path.GetFileName(pair.OutsideFile) + ")."));
            if (nanOccluded > 0) problems.Add((pair.OccludedFile, nanOccluded + " pixels without flow (NaN) are marked occluded: a pixel with no surface has both masks 0; the mask is inverted or of another pair."));
            if (outsideWrong > 0) problems.Add((pair.OutsideFile, outsideWrong + " pixels' outside mask disagrees with their flow (255 exactly where p + flow leaves frame b's image): the mask is inverted or of another pair."));
            if (alphaWrong > 0) problems.Add((pair.SceneFlowFile, alphaWrong + " pixels' A disagrees with the flow (A = 1 exactly where the pixel has flow or lies behind frame b's camera)."));
            return problems;
        }

        /// <summary>
        /// (d) against depth: the pixels where the flow says "surface" (finite, or behind b's camera) and where frame a's depth
        /// has one, counted where they disagree. Depth is sampled at the pixel centre on the rendered surface, the flow's ray
        /// meets the mesh's facets: they may differ on a silhouette pixel only.
        /// </summary>
        public static Counts SurfaceVsDepth(FlowPairFiles f, FlowCheckDepth depth)
        {
            var c = new Counts();
            for (var p = 0; p < depth.Z.Length; p++)
            {
                var flow = !float.IsNaN(f.Flow[2 * p]) || f.Outside[p] == 255;
                var seen = depth.Z[p] > 0;
                if (!flow && !seen) continue;
                c.Judged++;
                if (flow != seen) c.Bad++;
            }
            return c;
        }

        /// <summary>
        /// (a) Flow against depth, poses and scene flow: pixel p's point at a (back-projected from a's depth, away from depth
        /// edges), moved by its scene flow (0 on static parts: there this is exactly the camera-induced flow) and projected
        /// into b, must be where the flow puts it — within the flow the depth's uncertainty allows (the point at z ± δ) plus
        /// <see cref="FlowSlackPixels"/>. <paramref name="staticJudged"/> counts the static pixels among the judged.
        /// </summary>
        public static Counts CameraFlow(FlowPairFiles f, FlowCheckDepth depthA, CheckCamera a, CheckCamera b, int stride, out int staticJudged)
        {
            var c = new Counts();
            staticJudged = 0;
            int w = a.Width, h = a.Height;
            var delta = depthA.Uncertainty;
            for (var v = 0; v < h; v += stride)
                for (var u = 0; u < w; u += stride)
                {
                    var p = v * w + u;
                    if (!f.OnTarget[p] || float.IsNaN(f.Flow[2 * p]) || !depthA.Interior(u, v)) continue;
                    var z = depthA.At(u, v);
                    double sx = f.SceneFlow[3 * p], sy = f.SceneFlow[3 * p + 1], sz = f.SceneFlow[3 * p + 2];
                    if (!Target(a, b, u, v, z, sx, sy, sz, out var ex, out var ey, out _)) continue;
                    c.Judged++;
                    if (sx == 0 && sy == 0 && sz == 0) staticJudged++;
                    // The flow the depth's uncertainty allows: the point at z − δ and z + δ.
                    var allowed = 0.0;
                    foreach (var dz in new[] { -delta, delta })
                        if (z + dz > 0 && Target(a, b, u, v, z + dz, sx, sy, sz, out var tx, out var ty, out _))
                            allowed = Math.Max(allowed, Math.Sqrt((tx - ex) * (tx - ex) + (ty - ey) * (ty - ey)));
                    double fx = f.Flow[2 * p] - ex, fy = f.Flow[2 * p + 1] - ey;
                    var error = Math.Sqrt(fx * fx + fy * fy);
                    if (error > allowed + FlowSlackPixels)
                    {
                        c.Bad++;
                        c.Worst = Math.Max(c.Worst, error);
                    }
                }
            return c;
        }

        /// <summary>
        /// (b) Forward ∘ backward = identity: for p visible in a → b, B sampled bilinearly at p + F(p) must bring it back,
        /// |F(p) + B(p + F(p))| ≤ <see cref="InversePixels"/> + <see cref="InverseSpreadShare"/> × B's spread over the four
        /// pixels (per component, the larger), judged where the four pixels around p + F(p) are visible in
        /// b → a and (with b's depth) show one smooth surface.
        /// </summary>
        public static Counts Inverse(FlowPairFiles f, FlowPairFiles back, FlowCheckDepth depthB, int width, int height, int stride, List<double> residuals)
        {
            var c = new Counts();
            for (var v = 0; v < height; v += stride)
                for (var u = 0; u < width; u += stride)
                {
                    var p = v * width + u;
                    if (!Visible(f, p)) continue;
                    double qx = u + 0.5 + f.Flow[2 * p], qy = v + 0.5 + f.Flow[2 * p + 1];
                    double fx = qx - 0.5, fy = qy - 0.5;
                    var x0 = (int)Math.Floor(fx);
                    var y0 = (int)Math.Floor(fy);
                    if (x0 < 0 || y0 < 0 || x0 + 1 >= width || y0 + 1 >= height) continue;
                    var q = y0 * width + x0;
                    if (!Visible(back, q) || !Visible(back, q + 1) || !Visible(back, q + width) || !Visible(back, q + width + 1)) continue;
                    if (depthB != null && double.IsNaN(depthB.Smooth(qx, qy))) continue;
                    double ax = fx - x0, ay = fy - y0;
                    double bx = Bilinear(back.Flow, 2 * q, 2 * (q + 1), 2 * (q + width), 2 * (q + width + 1), ax, ay);
                    double by = Bilinear(back.Flow, 2 * q + 1, 2 * (q + 1) + 1, 2 * (q + width) + 1, 2 * (q + width + 1) + 1, ax, ay);
                    double rx = f.Flow[2 * p] + bx, ry = f.Flow[2 * p + 1] + by;
                    var r = Math.Sqrt(rx * rx + ry * ry);
                    c.Judged++;
                    residuals?.Add(r);
                    var spread = Math.Max(Spread(back.Flow, 2 * q, 2 * (q + 1), 2 * (q + width), 2 * (q + width + 1)), Spread(back.Flow, 2 * q + 1, 2 * (q + 1) + 1, 2 * (q + width) + 1, 2 * (q + width + 1) + 1));
                    if (r > InversePixels + InverseSpreadShare * spread)
                    {
                        c.Bad++;
                        c.Worst = Math.Max(c.Worst, r);
                    }
                }
            return c;
        }

        /// <summary>
        /// (c) Occlusion against depth: p's point at b (as in <see cref="CameraFlow"/>) has z-depth z_b there; b's depth d at
        /// its projection (bilinear, one smooth surface only) must be within max(δ_a + δ_b, 1 % of z_b) of z_b where p is
        /// marked visible, and nearer than z_b by more than δ_a + δ_b where p is marked occluded.
        /// </summary>
        public static Counts Occlusion(FlowPairFiles f, FlowCheckDepth depthA, FlowCheckDepth depthB, CheckCamera a, CheckCamera b, int stride, out int visibleBad, out int hiddenBad)
        {
            var c = new Counts();
            visibleBad = hiddenBad = 0;
            int w = a.Width, h = a.Height;
            for (var v = 0; v < h; v += stride)
                for (var u = 0; u < w; u += stride)
                {
                    var p = v * w + u;
                    if (!f.OnTarget[p] || f.Outside[p] != 0 || float.IsNaN(f.Flow[2 * p]) || !depthA.Interior(u, v)) continue;
                    if (!Target(a, b, u, v, depthA.At(u, v), f.SceneFlow[3 * p], f.SceneFlow[3 * p + 1], f.SceneFlow[3 * p + 2], out var ex, out var ey, out var zb)) continue;
                    var d = depthB.Smooth(u + 0.5 + ex, v + 0.5 + ey);
                    if (double.IsNaN(d)) continue;
                    // Visible: b's depth is the point's, within the depths' uncertainties or 1 % (bilinear depth across a
                    // pixel on a slope). Occluded: something is nearer by more than the uncertainties alone — a point just
                    // behind a limb is hidden by a surface only a little nearer, and a visible point marked occluded has
                    // b's depth equal to its own.
                    var uncertainty = depthA.Uncertainty + depthB.Uncertainty;
                    var tolerance = Math.Max(uncertainty, OcclusionRelative * zb);
                    var r = d - zb;
                    c.Judged++;
                    if (f.Occluded[p] == 0 && Math.Abs(r) > tolerance) { c.Bad++; visibleBad++; }
                    else if (f.Occluded[p] == 255 && r > -uncertainty) { c.Bad++; hiddenBad++; }
                }
            return c;
        }

        static double Spread(float[] values, int a, int b, int c, int d) =>
            Math.Max(Math.Max(values[a], values[b]), Math.Max(values[c], values[d])) - Math.Min(Math.Min(values[a], values[b]), Math.Min(values[c], values[d]));

        static bool Visible(FlowPairFiles f, int p) => !float.IsNaN(f.Flow[2 * p]) && f.Occluded[p] == 0 && f.Outside[p] == 0;

        static double Bilinear(float[] values, int i00, int i10, int i01, int i11, double ax, double ay) =>
            (values[i00] * (1 - ax) + values[i10] * ax) * (1 - ay) + (values[i01] * (1 - ax) + values[i11] * ax) * ay;

        /// <summary>Pixel (u, v) of a at z-depth z, moved by (sx, sy, sz), projected into b: the flow (ex, ey) and the z-depth at b.</summary>
        static bool Target(CheckCamera a, CheckCamera b, int u, int v, double z, double sx, double sy, double sz, out double ex, out double ey, out double zb)
        {
            ex = ey = zb = double.NaN;
            a.BackProject(u + 0.5, v + 0.5, z, out var x, out var y, out var w);
            if (!b.Project(x + sx, y + sy, w + sz, out var xb, out var yb, out zb)) return false;
            ex = xb - (u + 0.5);
            ey = yb - (v + 0.5);
            return true;
        }
    }
}
