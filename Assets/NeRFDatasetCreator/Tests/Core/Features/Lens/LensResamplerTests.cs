using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <see cref="LensResampler"/> on analytic wide pinhole renders (<see cref="LensCapture.WideRender"/> traced per
    /// sample, as the Unity camera renders it): known points land where the lens model puts them, depth is the z of
    /// each distorted pixel's own ray, and nothing is blended that must not be.
    /// </summary>
    [TestFixture]
    public class LensResamplerTests
    {
        static readonly CameraIntrinsics Frame = CameraIntrinsics.FromVerticalFov(60, 160, 120);

        static IEnumerable<LensDistortion> Lenses()
        {
            yield return LensDistortion.OpenCv(-0.25, 0.06, 0.003, -0.002);
            yield return LensDistortion.OpenCv(0.1, 0.01, 0, 0, 0.02); // pincushion with k3: the render is denser than the frame
            yield return LensDistortion.Fisheye(0.04, -0.01, 0.003, -0.0005);
        }

        [Test]
        public void TheWideRenderCoversTheFrameAndIsCentred([ValueSource(nameof(Lenses))] LensDistortion lens)
        {
            var wide = LensCapture.WideRender(lens, Frame);
            Assert.That(wide.Cx, Is.EqualTo(wide.Width / 2.0));
            Assert.That(wide.Cy, Is.EqualTo(wide.Height / 2.0));
            // What Unity renders from fieldOfView and aspect W/H: fy = (H/2)/tan(fov/2) and fx = fy, i.e. the focal.
            var fy = wide.Height / 2.0 / Math.Tan(wide.VerticalFovDegrees * Math.PI / 360);
            Assert.That(fy, Is.EqualTo(wide.Focal).Within(1e-9 * wide.Focal));
            var fx = wide.Width / 2.0 / (wide.Width / (double)wide.Height * Math.Tan(wide.VerticalFovDegrees * Math.PI / 360));
            Assert.That(fx, Is.EqualTo(wide.Focal).Within(1e-9 * wide.Focal));
            var cover = LensPinholeCover.For(lens, Frame);
            Assert.That(wide.Left, Is.GreaterThanOrEqualTo(Math.Max(cover.Left, cover.Right)));
            Assert.That(wide.Top, Is.GreaterThanOrEqualTo(Math.Max(cover.Top, cover.Bottom)));
            TestContext.WriteLine(lens.Describe() + ": " + wide.Width + "×" + wide.Height + " at f = " + wide.Focal.ToString("0.##") + ", " + wide.VerticalFovDegrees.ToString("0.##") + "° vertical, for a 160×120 frame at f = " + Frame.FlY.ToString("0.##"));
        }

        /// <summary>
        /// A wide render whose colour is the ray coordinate (x, y) of each sample (linear in the render's pixels, so
        /// bilinear sampling is exact) turns into a distorted frame whose colour at each sample is that sample's own
        /// undistorted ray; inverting it at known rays finds them where distort() puts them.
        /// </summary>
        [Test]
        public void KnownRaysLandWhereTheModelPutsThem([ValueSource(nameof(Lenses))] LensDistortion lens, [Values(1, 2)] int k)
        {
            var wide = LensCapture.WideRender(lens, Frame);
            var frame = new RawFrame(wide.Width * k, wide.Height * k, k) { ColorLinear = new float[wide.Width * k * wide.Height * k * 4] };
            for (var ys = 0; ys < frame.Height; ys++)
                for (var xs = 0; xs < frame.Width; xs++)
                {
                    var p = ((frame.Height - 1 - ys) * frame.Width + xs) * 4;
                    frame.ColorLinear[p] = (float)(((xs + 0.5) / k - wide.Cx) / wide.Focal);
                    frame.ColorLinear[p + 1] = (float)(((ys + 0.5) / k - wide.Cy) / wide.Focal);
                }
            var output = new LensResampler(lens, Frame, wide).Resample(frame);
            Assert.That(output.Width, Is.EqualTo(Frame.Width * k));
            Assert.That(output.Height, Is.EqualTo(Frame.Height * k));

            var worst = 0.0;
            var random = new Random(5);
            for (var n = 0; n < 200; n++)
            {
                // A known ray inside the frame, and where the model images it (output pixels, top-left origin).
                double u = 2 + random.NextDouble() * (Frame.Width - 4), v = 2 + random.NextDouble() * (Frame.Height - 4);
                Assert.That(lens.Undistort((u - Frame.Cx) / Frame.FlX, (v - Frame.Cy) / Frame.FlY, out var x, out var y), Is.True);
                lens.Distort(x, y, out var xd, out var yd);
                double expectedU = Frame.FlX * xd + Frame.Cx, expectedV = Frame.FlY * yd + Frame.Cy;
                var found = Locate(output, x, y);
                worst = Math.Max(worst, Math.Sqrt((found.Item1 - expectedU) * (found.Item1 - expectedU) + (found.Item2 - expectedV) * (found.Item2 - expectedV)));
            }
            TestContext.WriteLine(lens.Describe() + ", k = " + k + ": worst distance from the model's pixel " + worst.ToString("0.#####") + " px");
            Assert.That(worst, Is.LessThan(0.01), "px");
        }

        /// <summary>The output position (pixels, top-left origin) whose interpolated colour is the ray (x, y): the cell that holds it, inverse-bilinear by Newton.</summary>
        static Tuple<double, double> Locate(RawFrame output, double x, double y)
        {
            int w = output.Width, h = output.Height, k = output.Supersampling;
            double Get(int xs, int ys, int c) => output.ColorLinear[((h - 1 - ys) * w + xs) * 4 + c];
            // The sample whose ray is nearest, then refine in the 2×2 cell around the point.
            int bx = 0, by = 0;
            var best = double.MaxValue;
            for (var ys = 0; ys < h; ys++)
                for (var xs = 0; xs < w; xs++)
                {
                    var d = Math.Pow(Get(xs, ys, 0) - x, 2) + Math.Pow(Get(xs, ys, 1) - y, 2);
                    if (d < best) { best = d; bx = xs; by = ys; }
                }
            double s = bx, t = by;
            for (var iteration = 0; iteration < 20; iteration++)
            {
                int x0 = Math.Max(0, Math.Min(w - 2, (int)Math.Floor(s))), y0 = Math.Max(0, Math.Min(h - 2, (int)Math.Floor(t)));
                double a = s - x0, b = t - y0;
                double F(int c) => (Get(x0, y0, c) * (1 - a) + Get(x0 + 1, y0, c) * a) * (1 - b) + (Get(x0, y0 + 1, c) * (1 - a) + Get(x0 + 1, y0 + 1, c) * a) * b;
                double Ds(int c) => (Get(x0 + 1, y0, c) - Get(x0, y0, c)) * (1 - b) + (Get(x0 + 1, y0 + 1, c) - Get(x0, y0 + 1, c)) * b;
                double Dt(int c) => (Get(x0, y0 + 1, c) * (1 - a) + Get(x0 + 1, y0 + 1, c) * a) - (Get(x0, y0, c) * (1 - a) + Get(x0 + 1, y0, c) * a);
                double rx = F(0) - x, ry = F(1) - y, j00 = Ds(0), j01 = Dt(0), j10 = Ds(1), j11 = Dt(1), det = j00 * j11 - j01 * j10;
                s -= (rx * j11 - ry * j01) / det;
                t -= (ry * j00 - rx * j10) / det;
            }
            // Sample index s is the centre (s + ½)/k in output pixels.
            return Tuple.Create((s + 0.5) / k, (t + 0.5) / k);
        }

        /// <summary>
        /// Small spheres at known world points, traced in the wide render and resampled: each one's mask centroid in the
        /// distorted frame is where tracing the distorted rays directly puts it (the resampling's own error, within 0.1 px: both
        /// masks are hit-or-miss per sample, as the mask pass renders them, and alias differently on a 4-pixel disc),
        /// within 0.25 px of the model's projection of its centre (a sphere's image centroid is not exactly its centre's
        /// projection under perspective and distortion), and the depth at that pixel is its front's z.
        /// </summary>
        [Test]
        public void KnownPointsLandWhereTheModelPutsThem([ValueSource(nameof(Lenses))] LensDistortion lens)
        {
            const int k = 4; // 16 rays per pixel: the binary coverage of each ray leaves little aliasing in the centroids
            var wide = LensCapture.WideRender(lens, Frame);
            var scene = new AnalyticScene();
            var points = new List<Vector3d>();
            var random = new Random(3);
            while (points.Count < 12)
            {
                // A point in front of the camera (OpenGL axes, identity pose) whose image lies inside the frame with a margin.
                double u = 12 + random.NextDouble() * (Frame.Width - 24), v = 12 + random.NextDouble() * (Frame.Height - 24), z = 3 + random.NextDouble() * 2;
                lens.Undistort((u - Frame.Cx) / Frame.FlX, (v - Frame.Cy) / Frame.FlY, out var x, out var y);
                var centre = new Vector3d(x * z, -y * z, -z);
                if (points.Any(q => (q - centre).Length < 0.5)) continue;
                points.Add(centre);
                scene.Spheres.Add(new AnalyticScene.Sphere { Centre = centre, Radius = 0.04 * z, Colour = new[] { 1.0, 1.0, 1.0 } });
            }
            var options = new AnalyticDataset.Options();
            var rendered = AnalyticDataset.Render(scene, AnalyticDataset.Pinhole(Matrix4x4d.Identity, wide), wide.Width, wide.Height, options, 1, k);
            var output = new LensResampler(lens, Frame, wide).Resample(rendered);
            var direct = AnalyticDataset.Render(scene, AnalyticDataset.Rays(Matrix4x4d.Identity, Frame, lens), Frame.Width, Frame.Height, options, 1, k);
            double worst = 0, worstResampling = 0;
            foreach (var centre in points)
            {
                double x = centre.X / -centre.Z, y = -centre.Y / -centre.Z;
                lens.Distort(x, y, out var xd, out var yd);
                double eu = Frame.FlX * xd + Frame.Cx, ev = Frame.FlY * yd + Frame.Cy;
                var (ru, rv) = Centroid(output, eu, ev);
                var (du, dv) = Centroid(direct, eu, ev);
                worst = Math.Max(worst, Math.Sqrt(Math.Pow(ru - eu, 2) + Math.Pow(rv - ev, 2)));
                worstResampling = Math.Max(worstResampling, Math.Sqrt(Math.Pow(ru - du, 2) + Math.Pow(rv - dv, 2)));
                // Depth at the sample nearest the centre: the front of the sphere along that sample's own ray.
                int cxs = (int)Math.Floor(eu * k), cys = (int)Math.Floor(ev * k);
                double su0 = (cxs + 0.5) / k, sv0 = (cys + 0.5) / k;
                lens.Undistort((su0 - Frame.Cx) / Frame.FlX, (sv0 - Frame.Cy) / Frame.FlY, out var rx, out var ry);
                scene.Trace(Vector3d.Zero, new Vector3d(rx, -ry, -1), 0, out var t, out _, out _, out _);
                Assert.That(output.Depth[(output.Height - 1 - cys) * output.Width + cxs], Is.EqualTo(t).Within(1e-3 * t), "z of the sample's own ray");
            }
            TestContext.WriteLine(lens.Describe() + ": worst mask centroid " + worstResampling.ToString("0.####") + " px from the directly traced one, " + worst.ToString("0.####") + " px from the model's projection");
            Assert.That(worstResampling, Is.LessThan(0.1), "px, resampled vs traced along the distorted rays");
            // A 4-pixel sphere's image centroid sits off its centre's projection by the lens's curvature over the disc
            // (0.17 px for the pincushion lens here, the same in the direct trace): the exact placement is the test above.
            Assert.That(worst, Is.LessThan(0.25), "px, resampled vs the model's projection of the centre");
        }

        /// <summary>The mask's coverage-weighted centroid (output pixels) within 6 pixels of (u, v).</summary>
        static (double, double) Centroid(RawFrame frame, double u, double v)
        {
            int k = frame.Supersampling;
            double sum = 0, su = 0, sv = 0;
            for (var ys = 0; ys < frame.Height; ys++)
                for (var xs = 0; xs < frame.Width; xs++)
                {
                    double pu = (xs + 0.5) / k, pv = (ys + 0.5) / k;
                    if (Math.Abs(pu - u) > 6 || Math.Abs(pv - v) > 6) continue;
                    double m = frame.Mask[(frame.Height - 1 - ys) * frame.Width + xs];
                    sum += m; su += m * pu; sv += m * pv;
                }
            Assert.That(sum, Is.GreaterThan(0), "the sphere shows");
            return (su / sum, sv / sum);
        }

        /// <summary>On a tilted plane 1/z is affine in the pinhole image, so the resampled depth is the plane's z on each distorted ray.</summary>
        [Test]
        public void DepthOnATiltedPlaneIsExact([ValueSource(nameof(Lenses))] LensDistortion lens)
        {
            const int k = 1;
            var wide = LensCapture.WideRender(lens, Frame);
            var frame = new RawFrame(wide.Width * k, wide.Height * k, k) { Depth = new float[wide.Width * wide.Height * k * k] };
            // The plane n·X = 1 (camera axes, OpenCV: y down, z forward) with n = (0.1, 0.15, 0.25): 1/z = n·(x, y, 1).
            double nx = 0.1, ny = 0.15, nz = 0.25;
            for (var ys = 0; ys < frame.Height; ys++)
                for (var xs = 0; xs < frame.Width; xs++)
                {
                    double x = ((xs + 0.5) / k - wide.Cx) / wide.Focal, y = ((ys + 0.5) / k - wide.Cy) / wide.Focal;
                    frame.Depth[(frame.Height - 1 - ys) * frame.Width + xs] = (float)(1 / (nx * x + ny * y + nz));
                }
            var output = new LensResampler(lens, Frame, wide).Resample(frame);
            var worst = 0.0;
            for (var ys = 0; ys < output.Height; ys++)
                for (var xs = 0; xs < output.Width; xs++)
                {
                    lens.Undistort((xs + 0.5 - Frame.Cx) / Frame.FlX, (ys + 0.5 - Frame.Cy) / Frame.FlY, out var x, out var y);
                    var z = 1 / (nx * x + ny * y + nz);
                    worst = Math.Max(worst, Math.Abs(output.Depth[(output.Height - 1 - ys) * output.Width + xs] - z) / z);
                }
            TestContext.WriteLine(lens.Describe() + ": worst relative depth error " + worst.ToString("E2"));
            Assert.That(worst, Is.LessThan(1e-5));
        }

        [Test]
        public void DepthAndNormalsAreNeverBlendedAcrossAnEdge()
        {
            var lens = LensDistortion.OpenCv(-0.25, 0.06, 0.003, -0.002);
            var wide = LensCapture.WideRender(lens, Frame);
            var frame = new RawFrame(wide.Width, wide.Height, 1) { Depth = new float[wide.Width * wide.Height], Normals = new float[wide.Width * wide.Height * 4], Mask = new byte[wide.Width * wide.Height], MaskBytesPerPixel = 1 };
            // Left half: a surface at z = 2 facing +x; right half: z = 5 facing +y; a step between them.
            for (var j = 0; j < wide.Height; j++)
                for (var i = 0; i < wide.Width; i++)
                {
                    var p = j * wide.Width + i;
                    var left = i < wide.Width / 2;
                    frame.Depth[p] = left ? 2f : 5f;
                    frame.Normals[p * 4 + (left ? 0 : 1)] = 1;
                    frame.Mask[p] = left ? (byte)255 : (byte)0;
                }
            var output = new LensResampler(lens, Frame, wide).Resample(frame);
            // Only the two surfaces' z (to float rounding of the 1/z mix inside each surface), never a value between them.
            Assert.That(output.Depth.All(z => Math.Abs(z - 2) < 1e-5 || Math.Abs(z - 5) < 1e-5), Is.True, string.Join(", ", output.Depth.Distinct().Take(10)));
            for (var p = 0; p < output.Width * output.Height; p++)
            {
                var normal = output.Normals.Skip(p * 4).Take(4).ToArray();
                Assert.That(normal, Is.EqualTo(Math.Abs(output.Depth[p] - 2) < 1e-5 ? new float[] { 1, 0, 0, 0 } : new float[] { 0, 1, 0, 0 }), "the normal of the sample the depth came from");
            }
            // Coverage is interpolated (a partial value only along the edge), never lost.
            Assert.That(output.Mask.Count(m => m != 0 && m != 255), Is.LessThanOrEqualTo(2 * output.Height));
        }

        [Test]
        public void ReusedThreadBuffersGiveTheSameFrameWithoutNewArrays()
        {
            var lens = LensDistortion.OpenCv(-0.25, 0.06, 0.003, -0.002);
            var wide = LensCapture.WideRender(lens, Frame);
            RawFrame Wide(float z)
            {
                var frame = new RawFrame(wide.Width, wide.Height, 1) { Depth = new float[wide.Width * wide.Height], Mask = new byte[wide.Width * wide.Height], MaskBytesPerPixel = 1 };
                for (var p = 0; p < frame.Depth.Length; p++) { frame.Depth[p] = z + p % 7; frame.Mask[p] = (byte)(p % 256); }
                return frame;
            }
            var resampler = new LensResampler(lens, Frame, wide);
            var fresh = resampler.Resample(Wide(3));
            var first = resampler.Resample(Wide(3), reuseThreadBuffers: true);
            Assert.That(first.Depth, Is.EqualTo(fresh.Depth));
            Assert.That(first.Mask, Is.EqualTo(fresh.Mask));
            var second = resampler.Resample(Wide(5), reuseThreadBuffers: true);
            Assert.That(second.Depth, Is.SameAs(first.Depth), "the thread's array, reused");
            Assert.That(second.Depth, Is.EqualTo(resampler.Resample(Wide(5)).Depth));
        }

        [Test]
        public void LabelIdsTakeTheNearestSample()
        {
            var lens = LensDistortion.Fisheye(0.04, -0.01, 0.003, -0.0005);
            var wide = LensCapture.WideRender(lens, Frame);
            var ids = new ushort[wide.Width * wide.Height];
            for (var p = 0; p < ids.Length; p++) ids[p] = (ushort)(p % wide.Width < wide.Width / 3 ? 7 : 300);
            var resampler = new LensResampler(lens, Frame, wide);
            var output = new ushort[Frame.Width * Frame.Height];
            resampler.ResampleNearest(ids, 1, output, 1);
            Assert.That(output.Distinct().OrderBy(v => v), Is.EqualTo(new ushort[] { 7, 300 }), "ids are copied, never mixed");
        }

        [Test]
        public void AFrameOfAnotherSizeIsRefused_NamingTheRenderItNeeds()
        {
            var lens = LensDistortion.OpenCv(-0.1, 0, 0, 0);
            var wide = LensCapture.WideRender(lens, Frame);
            var frame = new RawFrame(Frame.Width, Frame.Height, 1) { Depth = new float[Frame.Width * Frame.Height] };
            var e = Assert.Throws<InvalidParameterException>(() => new LensResampler(lens, Frame, wide).Resample(frame));
            Assert.That(e.Message, Does.Contain(wide.Width + " × " + wide.Height));
        }
    }
}
