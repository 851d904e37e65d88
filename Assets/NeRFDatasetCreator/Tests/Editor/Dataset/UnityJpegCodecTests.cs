using NUnit.Framework;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The Editor's JPEG codec (UnityJpegCodec): installed on load, top row stays the top row through Unity's bottom-up
    /// arrays, and the quality the Replica export writes at keeps a smooth image above 35 dB (printed: Unity does not
    /// document its chroma subsampling, so the figure is measured here, not assumed).
    /// </summary>
    [TestFixture]
    public class UnityJpegCodecTests
    {
        [Test]
        public void TheEditorInstallsItsOwnEncoderAndRowsKeepTheirOrder()
        {
            Assert.That(JpegWriter.Codec, Is.Not.Null, "UnityJpegCodec installs itself on load ([InitializeOnLoadMethod])");
            Assert.That(JpegWriter.Codec.Name, Does.Contain("Unity"));
            const int w = 64, h = 48;
            var rgb = new byte[w * h * 3];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var i = 3 * (y * w + x);
                    // Bright top half, dark bottom half, a horizontal ramp in green: a flip or a mirror is obvious.
                    rgb[i] = (byte)(y < h / 2 ? 220 : 30);
                    rgb[i + 1] = (byte)(x * 255 / (w - 1));
                    rgb[i + 2] = 128;
                }
            var decoded = JpegWriter.DecodeRgb(JpegWriter.EncodeRgb(rgb, w, h), out var dw, out var dh);
            Assert.That(dw, Is.EqualTo(w));
            Assert.That(dh, Is.EqualTo(h));
            Assert.That(decoded[3 * (2 * w + 32)], Is.GreaterThan(180), "row 2 is bright: the top stays the top");
            Assert.That(decoded[3 * ((h - 3) * w + 32)], Is.LessThan(70), "row h − 3 is dark");
            Assert.That(decoded[3 * (10 * w + 2) + 1], Is.LessThan(decoded[3 * (10 * w + w - 3) + 1]), "green grows to the right");
            double sum = 0;
            for (var i = 0; i < rgb.Length; i++) sum += (rgb[i] - decoded[i]) * (double)(rgb[i] - decoded[i]);
            var psnr = 10 * System.Math.Log10(255.0 * 255.0 / (sum / rgb.Length));
            TestContext.WriteLine("Unity JPEG at quality " + JpegWriter.Quality + ": PSNR " + psnr.ToString("F2") + " dB");
            Assert.That(psnr, Is.GreaterThan(35));
        }
    }
}
