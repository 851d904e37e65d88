using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The size of the half-pixel convention difference, measured. bmild/nerf and nerf-pytorch (get_rays) shoot pixel
    /// (i, j) through image coordinate (i, j); nerfstudio (cameras.py get_image_coords, pixel_offset 0.5), instant-ngp
    /// (training uv continuous over the pixel, snapped to (i + 0.5)/W) and 3DGS (rasterizer ndc2Pix maps the frustum
    /// edge to −0.5, so pixel i's centre is i + 0.5 of the image) through (i + 0.5, j + 0.5) — which is where our
    /// renderer, like Blender, samples pixel centres. The difference is 0.5 px on each axis; these tests put numbers
    /// on it for Documentation~/using-the-data.md.
    /// </summary>
    public class HalfPixelConventionTests
    {
        static double Angle(double[] a, double[] b)
        {
            double dot = 0, na = 0, nb = 0;
            for (var k = 0; k < 3; k++) { dot += a[k] * b[k]; na += a[k] * a[k]; nb += b[k] * b[k]; }
            return Math.Acos(Math.Min(1, dot / Math.Sqrt(na * nb)));
        }

        [Test]
        public void OnTheLegoCameras_TheRaysDifferBy0point64Milliradians_About2point6MillimetresAtTheObject()
        {
            var json = JObject.Parse(File.ReadAllText(Fixtures.LegoTrainPath));
            var angleX = (double)json["camera_angle_x"];
            const int size = 800;
            var focal = 0.5 * size / Math.Tan(0.5 * angleX);
            Assert.That(focal, Is.EqualTo(1111.111).Within(1e-3), "camera_angle_x = 2·atan(0.36): f = 400/0.36");

            double maxAngle = 0, maxOffset = 0, sumOffset = 0;
            var count = 0;
            foreach (var frame in (JArray)json["frames"])
            {
                var c2w = frame["transform_matrix"].ToObject<double[][]>();
                var distance = Math.Sqrt(c2w[0][3] * c2w[0][3] + c2w[1][3] * c2w[1][3] + c2w[2][3] * c2w[2][3]);
                foreach (var i in new[] { 0, 200, 400, 799 })
                    foreach (var j in new[] { 0, 400, 799 })
                    {
                        NerfRays.Ray(c2w, angleX, size, size, i, j, out _, out var corner);
                        NerfRays.Ray(c2w, angleX, size, size, i + 0.5, j + 0.5, out _, out var centre);
                        var angle = Angle(corner, centre);
                        maxAngle = Math.Max(maxAngle, angle);
                        var offset = distance * Math.Tan(angle); // at the camera's distance to the origin, where the object is
                        maxOffset = Math.Max(maxOffset, offset);
                        sumOffset += offset;
                        count++;
                    }
            }
            TestContext.WriteLine($"lego 800×800: max angle {maxAngle * 1e3:F4} mrad, offset at the object max {maxOffset * 1e3:F3}, mean {sumOffset / count * 1e3:F3} thousandths of a unit");

            // By hand at the image centre: the two rays are 0.5·√2 px apart on the image plane at distance f.
            var centreAngle = Math.Atan(0.5 * Math.Sqrt(2) / focal);
            Assert.That(centreAngle, Is.EqualTo(6.364e-4).Within(1e-7));
            Assert.That(maxAngle, Is.EqualTo(centreAngle).Within(1e-9), "off-centre pixels see the same shift under a slightly smaller angle");
            Assert.That(maxOffset, Is.EqualTo(4.031 * 6.364e-4).Within(0.1e-3), "≈ 2.6e-3 output units at radius ≈ 4.03");
        }

        /// <summary>
        /// A hard-edged white disc (radius 100 px) on black at 400×400, coverage from 16×16 samples per pixel, against
        /// the same disc moved by t = (0.5, 0.5) px. By hand, an upper bound: an edge moved by t·n changes one pixel per
        /// unit of length by at most t·n, so Σ Δ² ≤ ∮ (t·n)² ds = π·R·|t|² = π·100·0.5 ≈ 157 (reached where the edge is
        /// aligned with the pixel grid; a slanted edge spreads the change over more pixels), i.e. PSNR ≥ 30.1 dB.
        /// Measured: Σ Δ² ≈ 127.5, PSNR ≈ 31.0 dB.
        /// </summary>
        [Test]
        public void AHalfPixelShiftOfAHardEdge_CostsAbout31Decibels()
        {
            const int w = 400, ss = 16;
            const double r = 100;
            double Coverage(int x, int y, double cx, double cy)
            {
                var inside = 0;
                for (var sy = 0; sy < ss; sy++)
                    for (var sx = 0; sx < ss; sx++)
                    {
                        double px = x + (sx + 0.5) / ss - cx, py = y + (sy + 0.5) / ss - cy;
                        if (px * px + py * py <= r * r) inside++;
                    }
                return inside / (double)(ss * ss);
            }
            double sum = 0;
            for (var y = 80; y < 320; y++) // the disc and its shifted copy lie inside this window; elsewhere both are 0
                for (var x = 80; x < 320; x++)
                {
                    var d = Coverage(x, y, 200, 200) - Coverage(x, y, 200.5, 200.5);
                    sum += d * d;
                }
            var psnr = 10 * Math.Log10(1 / (sum / (w * w)));
            TestContext.WriteLine($"half-pixel shift of a hard edge: PSNR {psnr:F2} dB (Σ Δ² = {sum:F1})");
            Assert.That(sum, Is.LessThanOrEqualTo(Math.PI * r * 0.5));
            Assert.That(sum, Is.GreaterThan(0.7 * Math.PI * r * 0.5), "most of the bound: the disc's edge is aligned with the grid over a large part of its length");
            Assert.That(psnr, Is.InRange(30.1, 31.5));
        }
    }
}
