using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class ChecksumTests
    {
        [Test]
        public void Crc32MatchesTheStandardCheckValue()
        {
            var data = System.Text.Encoding.ASCII.GetBytes("123456789");
            Assert.That(Crc32.Compute(data, 0, data.Length), Is.EqualTo(0xCBF43926u));
        }

        [Test]
        public void Adler32MatchesTheKnownValue()
        {
            var data = System.Text.Encoding.ASCII.GetBytes("Wikipedia");
            Assert.That(Adler32.Compute(data, 0, data.Length), Is.EqualTo(0x11E60398u));
        }

        // Lengths around Adler-32's 5552-byte modulo block, all-255 bytes being the worst case for overflow.
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(5551)]
        [TestCase(5552)]
        [TestCase(5553)]
        [TestCase(100000)]
        public void MatchTheBitwiseDefinitionsOnLongData(int length)
        {
            var data = new byte[length];
            var random = new SeededRandom(length);
            for (int i = 0; i < length; i++) data[i] = i % 3 == 0 ? (byte)255 : (byte)random.NextUInt64();
            Assert.That(Adler32.Compute(data, 0, length), Is.EqualTo(ReferencePngDecoder.SimpleAdler32(data)));
            Assert.That(Crc32.Compute(data, 0, length), Is.EqualTo(ReferencePngDecoder.BitwiseCrc32(data, 0, length)));
        }

        [Test]
        public void RunningUpdatesEqualOneShot()
        {
            var data = new byte[20000];
            var random = new SeededRandom(7);
            for (int i = 0; i < data.Length; i++) data[i] = (byte)random.NextUInt64();
            uint adler = Adler32.Update(Adler32.Update(Adler32.Start, data, 0, 7001), data, 7001, data.Length - 7001);
            uint crc = Crc32.Finish(Crc32.Update(Crc32.Update(Crc32.Start, data, 0, 7001), data, 7001, data.Length - 7001));
            Assert.That(adler, Is.EqualTo(ReferencePngDecoder.SimpleAdler32(data)));
            Assert.That(crc, Is.EqualTo(ReferencePngDecoder.BitwiseCrc32(data, 0, data.Length)));
        }
    }
}
