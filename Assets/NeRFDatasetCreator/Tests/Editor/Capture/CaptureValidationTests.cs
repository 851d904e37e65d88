using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Input checks that run before anything is created or rendered (no graphics device needed).</summary>
    [TestFixture]
    public class CaptureValidationTests
    {
        static readonly UnityPose Good = LookAt.FromPositions(new Vector3d(0, 0, -3), Vector3d.Zero);

        [Test]
        public void ANonFinitePoseIsRefusedNamingItsIndex()
        {
            var poses = new List<UnityPose> { Good, new UnityPose(new Vector3d(double.NaN, 0, 0), Quaterniond.Identity) };
            var e = Assert.Throws<InvalidParameterException>(() =>
                CaptureSession.Begin(null, poses, new CaptureOptions(), new RecordingConsumer()));
            Assert.That(e.Problems.Single().Field, Is.EqualTo("capture.poses[1]"));
            Assert.That(e.Problems.Single().Reason, Does.Contain("not finite"));
        }

        [Test]
        public void ANonUnitRotationIsRefused()
        {
            var poses = new List<UnityPose> { new UnityPose(Vector3d.Zero, new Quaterniond(0, 0, 0, 2)) };
            var e = Assert.Throws<InvalidParameterException>(() =>
                CaptureSession.Begin(null, poses, new CaptureOptions(), new RecordingConsumer()));
            Assert.That(e.Problems.Single().Reason, Does.Contain("unit length"));
        }

        [Test]
        public void AnEmptyPlanIsRefused()
        {
            var e = Assert.Throws<InvalidParameterException>(() =>
                CaptureSession.Begin(null, new List<UnityPose>(), new CaptureOptions(), new RecordingConsumer()));
            Assert.That(e.Problems.Single().Field, Is.EqualTo("capture.poses"));
        }

        [Test]
        public void BadOptionsAreRefusedBeforeAnythingElse()
        {
            var e = Assert.Throws<InvalidParameterException>(() =>
                CaptureSession.Begin(null, new List<UnityPose> { Good }, new CaptureOptions { Height = -1 }, new RecordingConsumer()));
            Assert.That(e.Problems.Select(p => p.Field), Is.EqualTo(new[] { "capture.height" }));
        }
    }
}
