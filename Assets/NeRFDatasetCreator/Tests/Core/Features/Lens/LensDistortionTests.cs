using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The two OpenCV lens models against values worked by hand from their formulas (COLMAP models.h
    /// OpenCVCameraModel / OpenCVFisheyeCameraModel::Distortion, nerfstudio camera_utils.py), and the Newton inverse
    /// against the forward model over whole frames.
    /// </summary>
    public class LensDistortionTests
    {
        const double Exact = 1e-15;

        // ---- forward model, by hand -------------------------------------------------------------------------------

        [Test]
        public void K1Only_ScalesByOnePlusK1RSquared()
        {
            // (0.3, 0.4): r² = 0.09 + 0.16 = 0.25; factor 1 + 0.1·0.25 = 1.025 → (0.3075, 0.41).
            LensDistortion.OpenCv(0.1, 0, 0, 0).Distort(0.3, 0.4, out var x, out var y);
            Assert.That(x, Is.EqualTo(0.3075).Within(Exact));
            Assert.That(y, Is.EqualTo(0.41).Within(Exact));
        }

        [Test]
        public void K2AndK3_AreTheR4AndR6Terms()
        {
            // r² = 0.25: k2 = 0.2 → factor 1 + 0.2·0.0625 = 1.0125; k3 = 0.1 → factor 1 + 0.1·0.015625 = 1.0015625.
            LensDistortion.OpenCv(0, 0.2, 0, 0).Distort(0.3, 0.4, out var x2, out var y2);
            Assert.That(x2, Is.EqualTo(0.30375).Within(Exact));
            Assert.That(y2, Is.EqualTo(0.405).Within(Exact));
            LensDistortion.OpenCv(0, 0, 0, 0, k3: 0.1).Distort(0.3, 0.4, out var x3, out var y3);
            Assert.That(x3, Is.EqualTo(0.30046875).Within(Exact));
            Assert.That(y3, Is.EqualTo(0.400625).Within(Exact));
        }

        [Test]
        public void P1Only_IsTheTangentialTermOfOpenCv()
        {
            // x_d = x + 2·p1·x·y = 0.3 + 2·0.01·0.12 = 0.3024; y_d = y + p1·(r² + 2y²) = 0.4 + 0.01·(0.25 + 0.32) = 0.4057.
            LensDistortion.OpenCv(0, 0, 0.01, 0).Distort(0.3, 0.4, out var x, out var y);
            Assert.That(x, Is.EqualTo(0.3024).Within(Exact));
            Assert.That(y, Is.EqualTo(0.4057).Within(Exact));
        }

        [Test]
        public void P2Only_IsTheOtherTangentialTerm()
        {
            // x_d = x + p2·(r² + 2x²) = 0.3 + 0.01·(0.25 + 0.18) = 0.3043; y_d = y + 2·p2·x·y = 0.4 + 0.0024 = 0.4024.
            LensDistortion.OpenCv(0, 0, 0, 0.01).Distort(0.3, 0.4, out var x, out var y);
            Assert.That(x, Is.EqualTo(0.3043).Within(Exact));
            Assert.That(y, Is.EqualTo(0.4024).Within(Exact));
        }

        [Test]
        public void FisheyeWithoutCoefficients_IsEquidistant()
        {
            // (0.6, 0.8): r = 1, θ = atan 1 = π/4, θ_d = θ → (0.6, 0.8)·(π/4)/1: the image radius is the angle.
            LensDistortion.Fisheye(0, 0, 0, 0).Distort(0.6, 0.8, out var x, out var y);
            Assert.That(x, Is.EqualTo(0.6 * Math.PI / 4).Within(Exact));
            Assert.That(y, Is.EqualTo(0.8 * Math.PI / 4).Within(Exact));
        }

        [Test]
        public void FisheyeK1_AtSixtyDegrees()
        {
            // (√3, 0): θ = atan √3 = π/3; θ_d = π/3·(1 + 0.1·(π/3)²) = π/3·(1 + π²/90); x_d = x·θ_d/r = θ_d.
            LensDistortion.Fisheye(0.1, 0, 0, 0).Distort(Math.Sqrt(3), 0, out var x, out var y);
            Assert.That(x, Is.EqualTo(Math.PI / 3 * (1 + Math.PI * Math.PI / 90)).Within(1e-14));
            Assert.That(y, Is.EqualTo(0));
        }

        [Test]
        public void FisheyeK2K3K4_AreTheTheta4To8Terms()
        {
            // (1, 0): θ = π/4 = t; θ_d = t(1 + 0.01 t⁴ + 0.001 t⁶ + 0.0001 t⁸).
            var t = Math.PI / 4;
            LensDistortion.Fisheye(0, 0.01, 0.001, 0.0001).Distort(1, 0, out var x, out _);
            Assert.That(x, Is.EqualTo(t * (1 + 0.01 * Math.Pow(t, 4) + 0.001 * Math.Pow(t, 6) + 0.0001 * Math.Pow(t, 8))).Within(1e-15));
        }

        [Test]
        public void TheCentreIsFixed_ForBothModels()
        {
            LensDistortion.OpenCv(-0.3, 0.1, 0.01, 0.02, 0.05).Distort(0, 0, out var x, out var y);
            Assert.That(new[] { x, y }, Is.EqualTo(new[] { 0.0, 0.0 }));
            LensDistortion.Fisheye(0.1, 0.01, 0.001, 0.0001).Distort(0, 0, out x, out y);
            Assert.That(new[] { x, y }, Is.EqualTo(new[] { 0.0, 0.0 }));
        }

        // ---- Newton inverse over whole frames ---------------------------------------------------------------------

        static readonly object[] Lenses =
        {
            new object[] { "realistic OPENCV", LensDistortion.OpenCv(-0.12, 0.03, 0.0007, -0.0004) },
            new object[] { "realistic FULL_OPENCV", LensDistortion.OpenCv(-0.28, 0.09, 0.001, 0.0005, -0.012) },
            new object[] { "strong OPENCV barrel", LensDistortion.OpenCv(-0.35, 0.12, 0.004, -0.003, -0.015) },
            new object[] { "strong OPENCV pincushion", LensDistortion.OpenCv(0.4, 0.2, -0.005, 0.006, 0.05) },
            new object[] { "realistic fisheye", LensDistortion.Fisheye(0.03, -0.004, 0.0006, -0.0001) },
            new object[] { "strong fisheye", LensDistortion.Fisheye(-0.15, 0.04, -0.01, 0.002) },
            new object[] { "equidistant fisheye", LensDistortion.Fisheye(0, 0, 0, 0) },
        };

        /// <summary>Every third pixel centre of a 77° × 62° frame (640×480 at fx = fy = 400, principal point off centre) is a distorted point.</summary>
        [TestCaseSource(nameof(Lenses))]
        public void DistortOfUndistort_IsTheIdentityOverTheFrame(string name, LensDistortion lens)
        {
            const double f = 400, cx = 323.5, cy = 236.25;
            var worst = 0.0;
            for (var row = 0; row < 480; row += 3)
                for (var col = 0; col < 640; col += 3)
                {
                    double xd = (col + 0.5 - cx) / f, yd = (row + 0.5 - cy) / f;
                    Assert.That(lens.Undistort(xd, yd, out var x, out var y), Is.True, name + " at pixel " + col + ", " + row);
                    lens.Distort(x, y, out var xBack, out var yBack);
                    worst = Math.Max(worst, Math.Max(Math.Abs(xBack - xd), Math.Abs(yBack - yd)));
                }
            Assert.That(worst, Is.LessThanOrEqualTo(1e-9), name);
        }

        [TestCaseSource(nameof(Lenses))]
        public void UndistortOfDistort_IsTheIdentityOverTheFrame(string name, LensDistortion lens)
        {
            // Ideal points across a ±45°-ish field; the inverse must find the very point that was distorted.
            var worst = 0.0;
            for (var i = -40; i <= 40; i++)
                for (var j = -30; j <= 30; j++)
                {
                    double x = i / 40.0, y = j / 40.0;
                    lens.Distort(x, y, out var xd, out var yd);
                    Assert.That(lens.Undistort(xd, yd, out var xBack, out var yBack), Is.True, name + " at " + x + ", " + y);
                    worst = Math.Max(worst, Math.Max(Math.Abs(xBack - x), Math.Abs(yBack - y)));
                }
            Assert.That(worst, Is.LessThanOrEqualTo(1e-9), name);
        }

        [Test]
        public void Undistort_ConvergesToTheStatedResidual()
        {
            var lens = LensDistortion.OpenCv(-0.35, 0.12, 0.004, -0.003, -0.015);
            Assert.That(lens.Undistort(0.5, -0.35, out var x, out var y), Is.True);
            lens.Distort(x, y, out var xd, out var yd);
            Assert.That(Math.Abs(xd - 0.5), Is.LessThanOrEqualTo(LensDistortion.Tolerance));
            Assert.That(Math.Abs(yd + 0.35), Is.LessThanOrEqualTo(LensDistortion.Tolerance));
        }

        [Test]
        public void Undistort_Fails_BeyondTheLensesReach()
        {
            // k1 = −0.5: r_d = r(1 − 0.5 r²) peaks at r² = 2/3 with r_d = √(2/3)·(2/3) ≈ 0.544; no ray images at r_d = 0.6.
            Assert.That(LensDistortion.OpenCv(-0.5, 0, 0, 0).Undistort(0.6, 0, out _, out _), Is.False);
            // k1 = −0.3 fisheye: θ_d = θ(1 − 0.3 θ²) peaks at θ = 1/√0.9 ≈ 1.054 with θ_d ≈ 0.703; no ray images at 0.75.
            Assert.That(LensDistortion.Fisheye(-0.3, 0, 0, 0).Undistort(0.75, 0, out _, out _), Is.False);
            // A fisheye image radius of π/2 or more is a ray at or behind 90°, which a perspective division cannot hold.
            Assert.That(LensDistortion.Fisheye(0, 0, 0, 0).Undistort(1.6, 0, out _, out _), Is.False);
        }

        [TestCaseSource(nameof(Lenses))]
        public void Jacobian_MatchesCentralDifferencesOfDistort(string name, LensDistortion lens)
        {
            const double h = 1e-5;
            foreach (var (x, y) in new[] { (0.0, 0.0), (0.3, -0.2), (-0.7, 0.45), (0.9, 0.6), (1e-9, 0) })
            {
                lens.Jacobian(x, y, out var a, out var b, out var c, out var d);
                lens.Distort(x + h, y, out var xp, out var yp);
                lens.Distort(x - h, y, out var xm, out var ym);
                lens.Distort(x, y + h, out var xq, out var yq);
                lens.Distort(x, y - h, out var xr, out var yr);
                Assert.That(new[] { a, b, c, d },
                    Is.EqualTo(new[] { (xp - xm) / (2 * h), (xq - xr) / (2 * h), (yp - ym) / (2 * h), (yq - yr) / (2 * h) }).Within(1e-8),
                    name + " at " + x + ", " + y);
            }
        }

        // ---- names, parameter lists, refusals ----------------------------------------------------------------------

        [Test]
        public void ColmapModelAndParameters_FollowModelsH()
        {
            var k = CameraIntrinsics.FromVerticalFov(60, 640, 480);
            var opencv = LensDistortion.OpenCv(0.1, 0.2, 0.3, 0.4);
            Assert.That(opencv.ColmapModelName, Is.EqualTo("OPENCV"));
            Assert.That(opencv.ColmapModelId, Is.EqualTo(4));
            Assert.That(opencv.ColmapParams(k), Is.EqualTo(new[] { k.FlX, k.FlY, k.Cx, k.Cy, 0.1, 0.2, 0.3, 0.4 }));
            // FULL_OPENCV: "fx, fy, cx, cy, k1, k2, p1, p2, k3, k4, k5, k6"; k4…k6 are its rational denominator, 0 here.
            var full = LensDistortion.OpenCv(0.1, 0.2, 0.3, 0.4, 0.5);
            Assert.That(full.ColmapModelName, Is.EqualTo("FULL_OPENCV"));
            Assert.That(full.ColmapModelId, Is.EqualTo(6));
            Assert.That(full.ColmapParams(k), Is.EqualTo(new[] { k.FlX, k.FlY, k.Cx, k.Cy, 0.1, 0.2, 0.3, 0.4, 0.5, 0, 0, 0 }));
            var fisheye = LensDistortion.Fisheye(0.1, 0.2, 0.3, 0.4);
            Assert.That(fisheye.ColmapModelName, Is.EqualTo("OPENCV_FISHEYE"));
            Assert.That(fisheye.ColmapModelId, Is.EqualTo(5));
            Assert.That(fisheye.ColmapParams(k), Is.EqualTo(new[] { k.FlX, k.FlY, k.Cx, k.Cy, 0.1, 0.2, 0.3, 0.4 }));
            Assert.That(fisheye.CameraModelName, Is.EqualTo("OPENCV_FISHEYE"));
            Assert.That(opencv.CameraModelName, Is.EqualTo("OPENCV"));
        }

        [Test]
        public void FullOpenCvWithZeroDenominator_IsOpenCvWithK3()
        {
            // COLMAP's FULL_OPENCV radial factor (1 + k1 r² + k2 r⁴ + k3 r⁶)/(1 + k4 r² + k5 r⁴ + k6 r⁶) with k4..k6 = 0,
            // written out here, is what our OPENCV + k3 computes.
            double k1 = -0.2, k2 = 0.05, p1 = 0.002, p2 = -0.001, k3 = 0.01, u = 0.4, v = -0.3;
            var r2 = u * u + v * v;
            var radial = (1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2) / 1.0;
            var xColmap = u * radial + 2 * p1 * u * v + p2 * (r2 + 2 * u * u);
            var yColmap = v * radial + 2 * p2 * u * v + p1 * (r2 + 2 * v * v);
            LensDistortion.OpenCv(k1, k2, p1, p2, k3).Distort(u, v, out var x, out var y);
            Assert.That(x, Is.EqualTo(xColmap).Within(1e-15));
            Assert.That(y, Is.EqualTo(yColmap).Within(1e-15));
        }

        [Test]
        public void CoefficientsAModelDoesNotHave_AreRefused()
        {
            var k4 = Assert.Throws<InvalidParameterException>(() => new LensDistortion(LensModel.OpenCv, 0.1, 0, 0, 0.2, 0, 0));
            Assert.That(k4.Problems[0].Field, Is.EqualTo("k4"));
            var p = Assert.Throws<InvalidParameterException>(() => new LensDistortion(LensModel.OpenCvFisheye, 0.1, 0, 0, 0, 0.01, 0));
            Assert.That(p.Problems[0].Field, Is.EqualTo("p1, p2"));
            var nan = Assert.Throws<InvalidParameterException>(() => LensDistortion.OpenCv(double.NaN, 0, 0, 0));
            Assert.That(nan.Problems[0].Field, Is.EqualTo("k1"));
        }

        [Test]
        public void OnlyAnOpenCvLensWithoutCoefficients_IsAPinhole()
        {
            Assert.That(LensDistortion.OpenCv(0, 0, 0, 0).IsPinhole, Is.True);
            Assert.That(LensDistortion.OpenCv(0, 0, 0, 1e-9).IsPinhole, Is.False);
            Assert.That(LensDistortion.Fisheye(0, 0, 0, 0).IsPinhole, Is.False);
        }
    }
}
