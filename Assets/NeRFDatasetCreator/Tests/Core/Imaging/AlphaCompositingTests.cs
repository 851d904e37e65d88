using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class AlphaCompositingTests
    {
        [Test]
        public void HalfCoverageOverWhiteRoundsToTheNearestCode()
        {
            // 200/255·128/255 + 1·127/255 = 0.891772… → ·255 = 227.40 → 227; the integer form: 58112 / 255 = 227.89 floored.
            Assert.That(AlphaCompositing.Over(200, 128, 255), Is.EqualTo(227));
            // Over black only the colour's share remains: 200·128/255 = 100.39 → 100.
            Assert.That(AlphaCompositing.Over(200, 128, 0), Is.EqualTo(100));
            // 10·3/255 + 255·252/255 = 252.12 → 252; a value at .5 rounds up: 1·(255−127)/255·255 … (1·128 + 0 + 127)/255 = 1.
            Assert.That(AlphaCompositing.Over(10, 3, 255), Is.EqualTo(252));
            Assert.That(AlphaCompositing.Over(1, 128, 0), Is.EqualTo(1));
        }

        [Test]
        public void OpaqueKeepsTheColourAndTransparentShowsTheBackground()
        {
            for (var c = 0; c < 256; c += 17)
            {
                Assert.That(AlphaCompositing.Over((byte)c, 255, 77), Is.EqualTo(c));
                Assert.That(AlphaCompositing.Over((byte)c, 0, 77), Is.EqualTo(77));
            }
        }

        [Test]
        public void EveryCombinationIsTheNearestCodeOfTheRealComposite()
        {
            for (var c = 0; c < 256; c += 5)
            for (var a = 0; a < 256; a++)
            for (var bg = 0; bg < 256; bg += 51)
            {
                var exact = (c * a + bg * (255.0 - a)) / 255.0;
                Assert.That(System.Math.Abs(AlphaCompositing.Over((byte)c, (byte)a, (byte)bg) - exact), Is.LessThanOrEqualTo(0.5), c + "," + a + "," + bg);
            }
        }

        [Test]
        public void OverSolidWritesOneTriplePerPixel()
        {
            var rgba = new byte[] { 200, 10, 0, 128, 9, 8, 7, 0 };
            var rgb = new byte[6];
            AlphaCompositing.OverSolid(rgba, rgb, 2, 255, 255, 255);
            Assert.That(rgb, Is.EqualTo(new byte[] { 227, 132, 127, 255, 255, 255 }));
        }
    }
}
