using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A 50 mm lens on a 36 × 24 mm sensor (aspect 1.5). By hand: the sensor height's angle is 2·atan(12/50) =
    /// 26.9915°; the sensor width spans a square image (a = 1) at 2·atan(18/50) = 39.5978° and an image twice as wide as
    /// high (a = 2) at 2·atan(18/(50·2)) = 20.4079° vertically.
    /// </summary>
    [TestFixture]
    public class PhysicalCameraFramingTests
    {
        const double SensorHeightAngle = 26.991466561591626;
        const double SquareHorizontalFit = 39.597752709049864;
        const double WideHorizontalFit = 20.407947443463367;

        static double Fov(GateFit fit, double aspect) => PhysicalCameraFraming.VerticalFovDegrees(50, 36, 24, 0, 0, fit, aspect);

        [TestCase(1.0)]
        [TestCase(2.0)]
        public void VerticalFitIsTheSensorHeightsAngleAtAnyAspect(double aspect)
        {
            Assert.That(Fov(GateFit.Vertical, aspect), Is.EqualTo(SensorHeightAngle).Within(1e-9));
        }

        [Test]
        public void HorizontalFitSpansTheImageWidthWithTheSensorWidth()
        {
            Assert.That(Fov(GateFit.Horizontal, 1), Is.EqualTo(SquareHorizontalFit).Within(1e-9));
            Assert.That(Fov(GateFit.Horizontal, 2), Is.EqualTo(WideHorizontalFit).Within(1e-9));
        }

        [Test]
        public void FillCropsTheSensorAndSoTakesTheSmallerAngle()
        {
            // Square image, narrower than the sensor: the height fits, the sensor's sides are cropped.
            Assert.That(Fov(GateFit.Fill, 1), Is.EqualTo(SensorHeightAngle).Within(1e-9));
            // Image wider than the sensor: the width fits, the sensor's top and bottom are cropped.
            Assert.That(Fov(GateFit.Fill, 2), Is.EqualTo(WideHorizontalFit).Within(1e-9));
        }

        [Test]
        public void OverscanShowsTheWholeSensorAndSoTakesTheLargerAngle()
        {
            Assert.That(Fov(GateFit.Overscan, 1), Is.EqualTo(SquareHorizontalFit).Within(1e-9));
            Assert.That(Fov(GateFit.Overscan, 2), Is.EqualTo(SensorHeightAngle).Within(1e-9));
        }

        [Test]
        public void NoneIsTheSensorsAngleWhenTheAspectsMatchAndRefusedOtherwise()
        {
            Assert.That(Fov(GateFit.None, 1.5), Is.EqualTo(SensorHeightAngle).Within(1e-9));
            var e = Assert.Throws<InvalidParameterException>(() => Fov(GateFit.None, 1));
            Assert.That(e.Message, Does.Contain("camera.copyFromCamera").And.Contain("not square"));
        }

        [Test]
        public void ALensShiftIsRefused()
        {
            var problem = PhysicalCameraFraming.Problem(50, 36, 24, 0.1, 0, GateFit.Vertical, 1);
            Assert.That(problem, Is.Not.Null);
            Assert.That(problem.Reason, Does.Contain("shifts the lens"));
            Assert.That(PhysicalCameraFraming.Problem(50, 36, 24, 0, 0, GateFit.Vertical, 1), Is.Null);
        }

        [Test]
        public void ASensorWithoutSizeIsRefused()
        {
            Assert.That(PhysicalCameraFraming.Problem(50, 0, 24, 0, 0, GateFit.Vertical, 1), Is.Not.Null);
            Assert.That(PhysicalCameraFraming.Problem(0, 36, 24, 0, 0, GateFit.Vertical, 1), Is.Not.Null);
        }

        [Test]
        public void TheEnumHasUnitysGateFitValues()
        {
            // Camera.GateFitMode: None 0, Vertical 1, Horizontal 2, Fill 3, Overscan 4 (the editor casts between them).
            Assert.That(new[] { (int)GateFit.None, (int)GateFit.Vertical, (int)GateFit.Horizontal, (int)GateFit.Fill, (int)GateFit.Overscan },
                Is.EqualTo(new[] { 0, 1, 2, 3, 4 }));
        }
    }
}
