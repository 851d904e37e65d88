using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>A fixed distance that leaves the target small in the frame is a plan warning suggesting "auto" (issue 33).</summary>
    [TestFixture]
    public class FramingWarningTests
    {
        [Test]
        public void ATinyTargetAtTheDefaultDistanceIsAWarningWithItsShareOfTheFrame()
        {
            // 800 × 800 at 39.59775° (nerf_synthetic): sin(19.798875°) = 0.33872 (tan 0.36 / √(1 + 0.36²)); a sphere of
            // radius 0.1 at distance 4 spans 0.1 / (4 × 0.33872) = 7.38 % of the side; "auto" is 1.2 × 0.1 / 0.33872 = 0.354.
            var settings = new DatasetSettings();
            var plan = CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.1));
            Assert.That(FramingWarning.Fill(0.1, 4, settings.Intrinsics()), Is.EqualTo(0.0738).Within(0.0001));
            var warning = plan.Warnings.Single(w => w.Field == "distance");
            Assert.That(warning.Value, Is.EqualTo("4"));
            Assert.That(warning.Reason, Is.EqualTo("leaves the target small: its bounding sphere (radius 0.1) spans 7.4 % of the image's narrower side (below 25 %), so most pixels are background and the target gets few rays."));
            Assert.That(warning.Fix, Is.EqualTo("Use \"distance\": \"auto\" (here 0.354, filling 83.3 %), or a smaller distance."));
        }

        [Test]
        public void ATargetThatFillsAQuarterOrAutoOrUnknownBoundsIsNoWarning()
        {
            var settings = new DatasetSettings();
            // Radius 0.5 at 4: 0.5 / 1.3549 = 36.9 %.
            Assert.That(CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.5)).Warnings.Where(w => w.Field == "distance"), Is.Empty);
            Assert.That(CapturePlan.Build(settings, PlanTarget.AtOrigin).Warnings.Where(w => w.Field == "distance"), Is.Empty, "the headless tool knows no size");
            settings.AutoDistance = true;
            Assert.That(CapturePlan.Build(settings, new PlanTarget(Vector3d.Zero, 0.1)).Warnings.Where(w => w.Field == "distance"), Is.Empty);
        }

        [Test]
        public void TheNarrowerSideCounts()
        {
            // 800 × 400 at a 39.59775° vertical field: the vertical one is the narrower, so the fill is the square case's.
            var settings = new DatasetSettings { Width = 800, Height = 400 };
            Assert.That(FramingWarning.Fill(0.1, 4, settings.Intrinsics()), Is.EqualTo(0.0738).Within(0.0001));
        }
    }
}
