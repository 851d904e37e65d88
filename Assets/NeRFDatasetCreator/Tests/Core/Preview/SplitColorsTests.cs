using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class SplitColorsTests
    {
        [Test]
        public void TrainIsOkabeItoSkyBlue()
        {
            var c = SplitColors.Of(PreviewSplit.Train);
            Assert.That(c.R, Is.EqualTo(86 / 255.0).Within(1e-6));
            Assert.That(c.G, Is.EqualTo(180 / 255.0).Within(1e-6));
            Assert.That(c.B, Is.EqualTo(233 / 255.0).Within(1e-6));
            Assert.That(c.A, Is.EqualTo(1.0));
        }

        [Test]
        public void ValIsOkabeItoOrangeAndTestReddishPurple()
        {
            Assert.That(SplitColors.Val.R, Is.EqualTo(230 / 255.0).Within(1e-6));
            Assert.That(SplitColors.Val.G, Is.EqualTo(159 / 255.0).Within(1e-6));
            Assert.That(SplitColors.Val.B, Is.EqualTo(0.0));
            Assert.That(SplitColors.Test.R, Is.EqualTo(204 / 255.0).Within(1e-6));
            Assert.That(SplitColors.Test.G, Is.EqualTo(121 / 255.0).Within(1e-6));
            Assert.That(SplitColors.Test.B, Is.EqualTo(167 / 255.0).Within(1e-6));
        }

        [Test]
        public void TheThreeSplitColoursDifferClearly()
        {
            // At least 0.25 apart in some channel: told apart at a glance, not just by a colour picker.
            var colours = new[] { SplitColors.Train, SplitColors.Val, SplitColors.Test };
            for (var i = 0; i < 3; i++)
                for (var j = i + 1; j < 3; j++)
                {
                    var d = System.Math.Max(System.Math.Abs(colours[i].R - colours[j].R),
                        System.Math.Max(System.Math.Abs(colours[i].G - colours[j].G), System.Math.Abs(colours[i].B - colours[j].B)));
                    Assert.That(d, Is.GreaterThan(0.25), i + " vs " + j);
                }
        }

        [TestCase(PreviewSplit.Train, "train")]
        [TestCase(PreviewSplit.Val, "val")]
        [TestCase(PreviewSplit.Test, "test")]
        public void SplitNamesAreTheDatasetFolderNames(PreviewSplit split, string name)
        {
            Assert.That(SplitColors.NameOf(split), Is.EqualTo(name));
        }
    }
}
