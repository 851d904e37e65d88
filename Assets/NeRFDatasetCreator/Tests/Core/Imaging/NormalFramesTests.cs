using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class NormalFramesTests
    {
        [Test]
        public void UnityUpBecomesOutputUpAndCoverageIsKept()
        {
            // Unity +Y (up) is the output world's +Z (up); Unity +Z is output +Y; no-hit pixels stay zero.
            var rgba = new[] { 0f, 1f, 0f, 1f, 0f, 0f, 1f, 1f, 0f, 0f, 0f, 0f };
            NormalFrames.ToOutputWorld(rgba);
            Assert.That(rgba, Is.EqualTo(new[] { 0f, 0f, 1f, 1f, 0f, 1f, 0f, 1f, 0f, 0f, 0f, 0f }));
        }
    }
}
