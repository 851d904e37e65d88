using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The depth-PNG reader returns exactly the samples written, whatever row filter the writer chose (PNG spec §9:
    /// None, Sub, Up, Average, Paeth); PngWriter's output is itself checked bit-exactly against the reference decoder.
    /// </summary>
    public class PngGray16ReaderTests
    {
        [TestCase(PngFilter.None)]
        [TestCase(PngFilter.Sub)]
        [TestCase(PngFilter.Up)]
        [TestCase(PngFilter.Average)]
        [TestCase(PngFilter.Paeth)]
        [TestCase(PngFilter.Adaptive)]
        public void ReadsBackEverySample(PngFilter filter)
        {
            const int w = 7, h = 5;
            var samples = new ushort[w * h];
            for (var i = 0; i < samples.Length; i++) samples[i] = (ushort)(i * 4099 % 65536); // high and low bytes both vary
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("d.png");
                File.WriteAllBytes(path, PngWriter.EncodeGray16(samples, w, h, PngCompression.Optimal, filter));
                Assert.That(PngGray16Reader.Read(path, out var width, out var height), Is.EqualTo(samples));
                Assert.That(width, Is.EqualTo(w));
                Assert.That(height, Is.EqualTo(h));
            }
        }

        [Test]
        public void AnRgbaPng_IsRefusedWithItsPath()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("c.png");
                TestPng.Write(path, 2, 2);
                var e = Assert.Throws<InvalidParameterException>(() => PngGray16Reader.Read(path, out _, out _));
                Assert.That(e.Problems[0].Value, Is.EqualTo(path));
            }
        }
    }
}
