using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class RawFrameTests
    {
        [Test]
        public void SizeNotAMultipleOfTheFactorIsReported()
        {
            var problems = new RawFrame(801, 800, 2).Validate();
            Assert.That(problems, Has.Count.EqualTo(1));
            Assert.That(problems[0].Field, Is.EqualTo("frame.Width"));
            Assert.That(problems[0].Fix, Does.Contain("800"));
        }

        [TestCase(0)]
        [TestCase(5)]
        public void FactorOutsideOneToFourIsReported(int k)
        {
            var problems = new RawFrame(20, 20, k).Validate();
            Assert.That(problems[0].Field, Is.EqualTo("frame.Supersampling"));
        }

        [Test]
        public void WrongArrayLengthsAreAllReportedAtOnce()
        {
            var frame = new RawFrame(4, 4, 2)
            {
                ColorSrgb = new byte[63],
                Mask = new byte[16],
                Depth = new float[15],
                Normals = new float[64],
            };
            var problems = frame.Validate();
            var fields = new System.Collections.Generic.List<string>();
            foreach (var p in problems) fields.Add(p.Field);
            Assert.That(fields, Is.EquivalentTo(new[] { "frame.ColorSrgb", "frame.Mask", "frame.Depth" }));
        }

        [Test]
        public void FlipRowsReversesRowOrder()
        {
            var destination = new int[6];
            RowOrder.FlipRows(new[] { 1, 2, 3, 4, 5, 6 }, destination, 2, 3);
            Assert.That(destination, Is.EqualTo(new[] { 5, 6, 3, 4, 1, 2 }));
        }
    }
}
