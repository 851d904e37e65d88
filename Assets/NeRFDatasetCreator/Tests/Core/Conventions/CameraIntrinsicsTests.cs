using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class CameraIntrinsicsTests
    {
        [Test]
        public void SixtyDegreeVerticalFovAt1920x1080()
        {
            var k = CameraIntrinsics.FromVerticalFov(60, 1920, 1080);
            // f = (H/2) / tan(30°) = 540·√3; hfov = 2·atan((W/2)/f) = 2·atan(16/(9·√3)).
            Assert.That(k.FlY, Is.EqualTo(540 * Math.Sqrt(3)).Within(1e-9));
            Assert.That(k.FlX, Is.EqualTo(k.FlY));
            Assert.That(k.CameraAngleY, Is.EqualTo(Math.PI / 3).Within(1e-12));
            Assert.That(k.CameraAngleX, Is.EqualTo(2 * Math.Atan(16 / (9 * Math.Sqrt(3)))).Within(1e-12));
            Assert.That(k.CameraAngleX * 180 / Math.PI, Is.EqualTo(91.4928).Within(1e-4), "the reference's 91.5° for 16:9");
            Assert.That(k.Cx, Is.EqualTo(960));
            Assert.That(k.Cy, Is.EqualTo(540));
            Assert.That(k.Width, Is.EqualTo(1920));
            Assert.That(k.Height, Is.EqualTo(1080));
        }

        [Test]
        public void HorizontalFovIsNotTheVerticalOneForNonSquareImages()
        {
            var k = CameraIntrinsics.FromVerticalFov(40, 800, 400);
            Assert.That(k.CameraAngleX, Is.GreaterThan(k.CameraAngleY));
            Assert.That(Math.Tan(k.CameraAngleX / 2) / Math.Tan(k.CameraAngleY / 2), Is.EqualTo(2).Within(1e-12));
        }

        [Test]
        public void VerticalFovRoundTripsThroughTheHorizontalOne()
        {
            var k = CameraIntrinsics.FromVerticalFov(33.3, 1024, 768);
            Assert.That(CameraIntrinsics.VerticalFovDegreesFromHorizontal(k.CameraAngleX, 1024, 768), Is.EqualTo(33.3).Within(1e-10));
        }

        [Test]
        public void LensShiftMovesThePrincipalPointOppositeToTheFrustum()
        {
            // An off-axis frustum shifted right by 0.1 of the sensor sees more on the right, so the optical axis
            // lands 0.1·W left of the centre; shifted up by 0.2, it lands 0.2·H below the centre (rows grow down).
            var k = CameraIntrinsics.FromVerticalFov(50, 1000, 500, 0.1, 0.2);
            Assert.That(k.Cx, Is.EqualTo(400).Within(1e-12));
            Assert.That(k.Cy, Is.EqualTo(350).Within(1e-12));
        }

        [TestCase(0.0, 800, 800, "verticalFovDegrees")]
        [TestCase(180.0, 800, 800, "verticalFovDegrees")]
        [TestCase(double.NaN, 800, 800, "verticalFovDegrees")]
        [TestCase(60.0, 0, 800, "width")]
        [TestCase(60.0, 800, 20000, "height")]
        public void OutOfRangeValuesNameTheParameter(double fov, int width, int height, string parameter)
        {
            var error = Assert.Throws<InvalidParameterException>(() => CameraIntrinsics.FromVerticalFov(fov, width, height));
            Assert.That(error.Message, Does.Contain(parameter));
            Assert.That(error.Problems[0].Field, Is.EqualTo(parameter));
        }
    }
}
