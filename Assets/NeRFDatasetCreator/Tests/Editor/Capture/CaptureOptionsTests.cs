using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Editor.Tests
{
    [TestFixture]
    public class CaptureOptionsTests
    {
        [Test]
        public void DefaultsAreValid()
        {
            Assert.That(new CaptureOptions().Validate(), Is.Empty);
        }

        [Test]
        public void EveryProblemIsReportedAtOnceNamingItsField()
        {
            var options = new CaptureOptions { Width = 0, Supersampling = 9, VerticalFieldOfViewDegrees = 180, NearClip = 1, FarClip = 0.5 };
            var fields = options.Validate().Select(p => p.Field).ToList();
            Assert.That(fields, Is.EquivalentTo(new[] { "capture.width", "capture.supersampling", "capture.verticalFieldOfViewDegrees", "capture.farClip" }));
        }

        [Test]
        public void SupersamplingBeyondCoresLimitIsRefused()
        {
            // The writer (RawFrame) refuses k > 4: the capture must refuse it before rendering anything.
            Assert.That(new CaptureOptions { Supersampling = RawFrame.MaxSupersampling }.Validate(), Is.Empty);
            var problem = new CaptureOptions { Supersampling = RawFrame.MaxSupersampling + 1 }.Validate().Single();
            Assert.That(problem.Field, Is.EqualTo("capture.supersampling"));
        }

        [Test]
        public void SupersampledSizeBeyondGpuLimitsIsRefused()
        {
            var options = new CaptureOptions { Width = 8000, Height = 100, Supersampling = 4 };
            var problem = options.Validate().Single();
            Assert.That(problem.Field, Is.EqualTo("capture.supersampling"));
            Assert.That(problem.Reason, Does.Contain("32000"));
        }

        [Test]
        public void ColourNoLongerBringsTheMaskItsAlphaComesFromMatting()
        {
            var options = new CaptureOptions { Passes = CapturePasses.Color | CapturePasses.Depth };
            Assert.That(options.EffectivePasses, Is.EqualTo(CapturePasses.Color | CapturePasses.Depth));
        }

        [Test]
        public void DepthAndNormalsAreAtOutputSizeByDefault()
        {
            var options = new CaptureOptions { Width = 30, Height = 20, Supersampling = 3 };
            Assert.That(options.SupersampledWidth, Is.EqualTo(90));
            Assert.That(options.SupersampledHeight, Is.EqualTo(60));
            Assert.That(options.DataWidth, Is.EqualTo(30));
            Assert.That(options.DataHeight, Is.EqualTo(20));
            options.DepthAndNormalAtOutputSize = false;
            Assert.That(options.DataWidth, Is.EqualTo(90));
        }
    }
}
