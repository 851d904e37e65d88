using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SlamSequenceTests
    {
        [Test]
        public void DepthBeyondTheFormatsRangeBecomesNoMeasurementAndIsCounted()
        {
            using (var temp = new TempFolder())
            {
                // Codes at 1/1000 unit: 0 (no hit), 5 units, 9.9999 units, 10.001 units (past 65535 / 6553.5 = 10), 13 units.
                var codes = new ushort[] { 0, 5000, 9999, 10001, 13000, 13200 };
                File.WriteAllBytes(temp.Combine("d.png"), PngWriter.EncodeGray16(codes, 6, 1));
                File.WriteAllBytes(temp.Combine("c.png"), PngWriter.Encode(new byte[18], 6, 1, PngPixelFormat.Rgb8));
                var scene = new ExportScene(temp.Path, CameraIntrinsics.FromVerticalFov(40, 6, 1), new[] { new ExportFrame("train", "c.png", Matrix4x4d.Identity, "d.png") });
                long beyond = 0;
                var replica = SlamSequence.Depth(scene, scene.Frames[0], Replica.DepthScale, ref beyond, out _, out _);
                Assert.That(replica, Is.EqualTo(new ushort[] { 0, 32768, 65528, 0, 0, 0 })); // 5·6553.5 = 32767.5 → 32768; 9.999·6553.5 = 65528.4
                Assert.That(beyond, Is.EqualTo(3));
                beyond = 0;
                var tum = SlamSequence.Depth(scene, scene.Frames[0], TumRgbd.DepthScale, ref beyond, out _, out _);
                Assert.That(tum, Is.EqualTo(new ushort[] { 0, 25000, 49995, 50005, 65000, 0 })); // 13.2 · 5000 = 66000 > 65535
                Assert.That(beyond, Is.EqualTo(1));
                var warning = SlamSequence.RangeWarning("depth", beyond, 6, TumRgbd.DepthScale, "TUM RGB-D");
                Assert.That(warning.Value, Is.EqualTo("1 of 6 depth pixels"));
                Assert.That(warning.Reason, Does.StartWith("are farther than 13.107 output units"));
                Assert.That(SlamSequence.RangeWarning("depth", 0, 6, 5000, "TUM RGB-D"), Is.Null);
            }
        }

        [Test]
        public void ALensIsRefusedForBothSlamTargetsAndAPinholeIsNot()
        {
            var lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 }.ToDistortion();
            foreach (var target in new[] { ExportTarget.Replica, ExportTarget.Tum })
            {
                var refusal = LensExports.Refusal(lens, target);
                Assert.That(refusal.Field, Is.EqualTo("--to"));
                Assert.That(refusal.Value, Is.EqualTo(ExportTargets.Name(target)));
                Assert.That(refusal.Reason, Does.StartWith("cannot hold lens distortion"));
                Assert.That(LensExports.Refusal(null, target), Is.Null);
            }
        }

        [Test]
        public void JpegAtTheStatedQualityRoundTripsAboveFortyDecibelsAndIsDeterministic()
        {
            // A smooth colour ramp with one hard edge, 33 × 17 (not a multiple of the 8-pixel block).
            int w = 33, h = 17;
            var rgb = new byte[w * h * 3];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    var o = 3 * (y * w + x);
                    rgb[o] = (byte)(x * 7);
                    rgb[o + 1] = (byte)(y * 15);
                    rgb[o + 2] = (byte)(x < 16 ? 40 : 200);
                }
            var jpeg = JpegWriter.EncodeRgb(rgb, w, h);
            Assert.That(jpeg.Take(2), Is.EqualTo(new byte[] { 0xFF, 0xD8 }), "SOI");
            Assert.That(JpegWriter.EncodeRgb(rgb, w, h), Is.EqualTo(jpeg));
            var decoded = JpegWriter.DecodeRgb(jpeg, out var dw, out var dh);
            Assert.That(dw, Is.EqualTo(w));
            Assert.That(dh, Is.EqualTo(h));
            var psnr = SlamTestData.Psnr(decoded, rgb);
            TestContext.Progress.WriteLine("JPEG q" + JpegWriter.Quality + " ramp PSNR " + psnr.ToString("F2") + " dB");
            Assert.That(psnr, Is.GreaterThan(40));
            Assert.That(SlamTestData.Psnr(JpegWriter.DecodeRgb(JpegWriter.EncodeRgb(rgb, w, h, 20), out _, out _), rgb), Is.LessThan(psnr), "quality matters");
        }
    }
}
