using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Drawing through a <see cref="PaintersBuffer"/> in any order gives the picture of drawing sorted far to near.</summary>
    [TestFixture]
    public class PaintersBufferTests
    {
        static readonly byte[] Red = { 255, 0, 0 }, Green = { 0, 255, 0 }, Blue = { 0, 0, 255 }, Black = { 0, 0, 0 };

        // Three overlapping discs: (depth, index, colour). Sorted ascending by depth then index: blue (1, 2), red (2, 0), green (2, 1).
        static readonly (double depth, int index, byte[] colour, double x)[] Items = { (2, 0, Red, 10), (2, 1, Green, 13), (1, 2, Blue, 16) };

        static byte[] Painted(bool descending, int[] order, bool buffered)
        {
            var canvas = new RgbCanvas(30, 20, Black);
            var painter = new PaintersBuffer(0, 0, 30, 20, descending);
            if (buffered) canvas.Filter = painter.Accept;
            foreach (var k in order)
            {
                var (depth, index, colour, x) = Items[k];
                painter.Item(depth, index, 0);
                canvas.FillDisc(x, 10, 5, colour);
            }
            return canvas.Pixels;
        }

        [Test]
        public void AnyOrderGivesTheSortedPicture()
        {
            var ascending = Painted(false, new[] { 2, 0, 1 }, buffered: false); // blue, red, green: the sorted order
            var descending = Painted(true, new[] { 0, 1, 2 }, buffered: false); // red, green, blue: far (2) to near (1), ties by index
            foreach (var order in new[] { new[] { 0, 1, 2 }, new[] { 2, 1, 0 }, new[] { 1, 2, 0 } })
            {
                Assert.That(Painted(false, order, buffered: true), Is.EqualTo(ascending));
                Assert.That(Painted(true, order, buffered: true), Is.EqualTo(descending));
            }
            Assert.That(ascending, Is.Not.EqualTo(descending));
        }

        [Test]
        public void ALaterLayerOfOneItemCoversItsEarlierOne()
        {
            var canvas = new RgbCanvas(10, 10, Black);
            var painter = new PaintersBuffer(0, 0, 10, 10, descending: false);
            canvas.Filter = painter.Accept;
            painter.Item(0, 0, 1);
            canvas.Set(4, 4, Red);
            painter.Item(0, 0, 0);
            canvas.Set(4, 4, Green); // an earlier layer drawn later stays under
            Assert.That(canvas.Get(4, 4), Is.EqualTo(Red));
        }
    }
}
