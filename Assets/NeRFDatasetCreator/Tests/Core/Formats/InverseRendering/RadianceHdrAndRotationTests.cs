using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The .hdr encoding of the environment maps and their rotation about +Z, against hand-computed values.</summary>
    [TestFixture]
    public class RadianceHdrAndRotationTests
    {
        [Test]
        public void RgbeBytesAreRadiancesFrexpOfTheLargestComponent()
        {
            // 1 = 0.5·2^1: e = 1 + 128, scale 0.5·256 / 1 = 128 → (128, 64, 32, 129); black is (0, 0, 0, 0).
            var bytes = new byte[8];
            RadianceHdr.Rgbe(1, 0.5, 0.25, bytes, 0);
            RadianceHdr.Rgbe(0, 0, 0, bytes, 4);
            Assert.That(bytes, Is.EqualTo(new byte[] { 128, 64, 32, 129, 0, 0, 0, 0 }));
            // 3 = 0.75·2^2: scale 0.75·256 / 3 = 64 → (192, 0, 0, 130).
            RadianceHdr.Rgbe(3, 0, 0, bytes, 0);
            Assert.That(bytes[0], Is.EqualTo(192));
            Assert.That(bytes[3], Is.EqualTo(130));
        }

        [Test]
        public void NarrowImagesAreWrittenFlatAndReadBack()
        {
            // Width 4 < 8: no run-length form; each pixel is four bytes after the header.
            var pixels = new float[] { 1, 0.5f, 0.25f, 0, 0, 0, 2, 2, 2, 0.125f, 0, 0 };
            var file = RadianceHdr.Encode(pixels, 4, 1, 3);
            var header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 4\n";
            Assert.That(file.Length, Is.EqualTo(header.Length + 16));
            Assert.That(new[] { file[header.Length], file[header.Length + 1], file[header.Length + 2], file[header.Length + 3] }, Is.EqualTo(new byte[] { 128, 64, 32, 129 }));
        }

        [Test]
        public void ARotationShiftsColumnsByMinusThetaOver360OfTheWidthBetweenNeighbours()
        {
            // 8 columns, value = column index; 10° is 8·10/360 = 0.2222 of a column: column 7 samples 7.2222,
            // i.e. 0.7778·column 7 + 0.2222·column 0 (wrapping) = 5.4444.
            var red = new float[8];
            for (var x = 0; x < 8; x++) red[x] = x;
            var map = new ExrImage(8, 1, new Dictionary<string, float[]> { ["R"] = red, ["G"] = new float[8], ["B"] = new float[8] });
            var rotated = InverseRenderingLight.Rotate(map, 10);
            Assert.That(rotated[3 * 7], Is.EqualTo(7 * (1 - 8 * 10 / 360.0)).Within(1e-5));
            Assert.That(rotated[3 * 0], Is.EqualTo(8 * 10 / 360.0).Within(1e-5));
            Assert.That(InverseRenderingLight.Rotate(map, 90)[0], Is.EqualTo(2), "90° is a quarter of the width: column 0 shows column 2");
        }
    }
}
