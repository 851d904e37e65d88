using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The pinhole render that covers a distorted frame: extents and focal worked out independently of the Newton inverse.</summary>
    public class LensPinholeCoverTests
    {
        static readonly CameraIntrinsics Frame = CameraIntrinsics.FromVerticalFov(60, 640, 480); // cx 320, cy 240

        /// <summary>r with r(1 + k1 r²) = rd on the rising branch, by bisection (independent of LensDistortion.Undistort).</summary>
        static double RadialInverse(double k1, double rd)
        {
            double lo = 0, hi = k1 < 0 ? Math.Sqrt(-1 / (3 * k1)) : rd;
            for (var i = 0; i < 200; i++)
            {
                var mid = 0.5 * (lo + hi);
                if (mid * (1 + k1 * mid * mid) < rd) lo = mid; else hi = mid;
            }
            return 0.5 * (lo + hi);
        }

        [Test]
        public void WithoutDistortion_TheCoverIsTheFrameItself()
        {
            var cover = LensPinholeCover.For(LensDistortion.OpenCv(0, 0, 0, 0), Frame);
            Assert.That(cover.Width, Is.EqualTo(640));
            Assert.That(cover.Height, Is.EqualTo(480));
            Assert.That(cover.Focal, Is.EqualTo(Frame.FlX).Within(1e-9));
            Assert.That(cover.Cx, Is.EqualTo(320).Within(1e-9));
            Assert.That(cover.Cy, Is.EqualTo(240).Within(1e-9));
        }

        [Test]
        public void Barrel_WidensTheRenderToTheUndistortedCorner_AtTheSameFocal()
        {
            const double k1 = -0.1;
            var f = Frame.FlX;
            double xd = 320 / f, yd = 240 / f, rd = Math.Sqrt(xd * xd + yd * yd);
            var r = RadialInverse(k1, rd); // the corner's ideal radius; barrel pushes it outward
            var cover = LensPinholeCover.For(LensDistortion.OpenCv(k1, 0, 0, 0), Frame);
            Assert.That(cover.Right, Is.EqualTo(xd * r / rd).Within(1e-9));
            Assert.That(cover.Bottom, Is.EqualTo(yd * r / rd).Within(1e-9));
            Assert.That(cover.Left, Is.EqualTo(cover.Right).Within(1e-12), "symmetric frame");
            Assert.That(cover.Focal, Is.EqualTo(f).Within(1e-6), "barrel shrinks outward: the centre's density is the finest needed");
            Assert.That(cover.Width, Is.EqualTo((int)Math.Ceiling(f * 2 * xd * r / rd)));
            Assert.That(cover.Width, Is.GreaterThan(640));
        }

        [Test]
        public void Pincushion_RaisesTheFocal_ToTheCornersRadialStretch()
        {
            // Radial-only lens: the Jacobian's singular values are 1 + k1 r² (tangential) and 1 + 3 k1 r² (radial).
            const double k1 = 0.1;
            var f = Frame.FlX;
            double xd = 320 / f, yd = 240 / f, rd = Math.Sqrt(xd * xd + yd * yd);
            var r = RadialInverse(k1, rd);
            var cover = LensPinholeCover.For(LensDistortion.OpenCv(k1, 0, 0, 0), Frame);
            Assert.That(cover.Focal, Is.EqualTo(f * (1 + 3 * k1 * r * r)).Within(1e-6 * f));
            // Pincushion pulls the edges in most on the axis: the widest ray of the right edge is its midpoint (y = 0).
            Assert.That(cover.Right, Is.EqualTo(RadialInverse(k1, xd)).Within(1e-9));
            Assert.That(cover.Width, Is.EqualTo((int)Math.Ceiling(cover.Focal * 2 * RadialInverse(k1, xd) - 1e-6)));
        }

        [Test]
        public void Fisheye_CoversTheCornerRay()
        {
            // Equidistant, f = 320/0.9: the frame's corner is at image radius ρ = √(0.9² + 0.675²) = 1.125 = θ,
            // so its ray is at x = tan(1.125)·0.9/1.125 ≈ 1.67 (the side's midpoint only at tan 0.9 ≈ 1.26).
            var k = CameraIntrinsics.FromVerticalFov(2 * Math.Atan(240 / (320 / 0.9)) * 180 / Math.PI, 640, 480);
            var cover = LensPinholeCover.For(LensDistortion.Fisheye(0, 0, 0, 0), k);
            var rho = Math.Sqrt(0.9 * 0.9 + 0.675 * 0.675);
            Assert.That(cover.Right, Is.EqualTo(Math.Tan(rho) * 0.9 / rho).Within(1e-9));
            Assert.That(cover.Bottom, Is.EqualTo(Math.Tan(rho) * 0.675 / rho).Within(1e-9));
        }

        [Test]
        public void AFisheyeWiderThanTheCap_IsRefused_NamingTheRender()
        {
            // Image radius 1.2 rad at the sides, 1.5 rad (86°) at the corners: the corner ray is at x = tan(1.5)·0.8 ≈ 11.3,
            // so the pinhole would span 2·atan 11.3 ≈ 170° across, beyond MaxFovDegrees.
            var k = CameraIntrinsics.FromVerticalFov(2 * Math.Atan(240 / (320 / 1.2)) * 180 / Math.PI, 640, 480);
            var e = Assert.Throws<InvalidParameterException>(() => LensPinholeCover.For(LensDistortion.Fisheye(0, 0, 0, 0), k));
            Assert.That(e.Problems[0].Reason, Does.Contain("needs a pinhole render of").And.Contain("150°"));
            // At 1.4 rad at the sides the corner looks beyond 90°: no pinhole can hold it at all.
            var beyond = CameraIntrinsics.FromVerticalFov(2 * Math.Atan(240 / (320 / 1.4)) * 180 / Math.PI, 640, 480);
            e = Assert.Throws<InvalidParameterException>(() => LensPinholeCover.For(LensDistortion.Fisheye(0, 0, 0, 0), beyond));
            Assert.That(e.Problems[0].Reason, Does.Contain("90°"));
        }

        [Test]
        public void ALensThatFoldsInsideTheFrame_IsRefused()
        {
            // k1 = −0.5 folds at r_d ≈ 0.544; this frame's corner is at r_d = 400/f ≈ 0.72.
            var e = Assert.Throws<InvalidParameterException>(() => LensPinholeCover.For(LensDistortion.OpenCv(-0.5, 0, 0, 0), Frame));
            Assert.That(e.Problems[0].Reason, Does.Contain("images no ray"));
        }
    }
}
