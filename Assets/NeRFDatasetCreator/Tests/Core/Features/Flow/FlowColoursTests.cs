using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The Middlebury colour code: values worked from colorcode.cpp's formula (the wheel's 55 colours, atan2(−fy, −fx),
    /// desaturation by the length, 75 % outside the unit circle) and the same vectors run through RAFT's
    /// flow_viz.compute_color by hand (it printed exactly these).
    /// </summary>
    public class FlowColoursTests
    {
        static byte[] Of(double fx, double fy)
        {
            var rgb = new byte[3];
            FlowColours.Colour(fx, fy, rgb, 0);
            return rgb;
        }

        [Test]
        public void TheWheelGivesMiddleburysColours()
        {
            Assert.That(Of(1, -0.0), Is.EqualTo(new byte[] { 255, 0, 43 }), "right: the wheel's last colour (angle π)");
            Assert.That(Of(0, 1), Is.EqualTo(new byte[] { 255, 229, 0 }), "down: halfway between wheel colours 13 and 14");
            Assert.That(Of(-1, -0.0), Is.EqualTo(new byte[] { 0, 209, 255 }), "left: colour 27");
            Assert.That(Of(0, 0), Is.EqualTo(new byte[] { 255, 255, 255 }), "no motion: white");
            Assert.That(Of(2, -0.0), Is.EqualTo(new byte[] { 191, 0, 32 }), "beyond the range: 75 %");
            Assert.That(Of(0.3, -0.4), Is.EqualTo(new byte[] { 225, 127, 255 }), "half length: half saturated");
        }

        [Test]
        public void APictureScalesByTheLongestVectorAndLeavesNoFlowBlack()
        {
            var flow = new float[] { 4, 0, float.NaN, float.NaN, 0, 2 };
            var rgb = FlowColours.Picture(flow, 3, 1);
            Assert.That(new[] { rgb[0], rgb[1], rgb[2] }, Is.EqualTo(Of(1, 0)), "the longest vector at full saturation");
            Assert.That(new[] { rgb[3], rgb[4], rgb[5] }, Is.EqualTo(new byte[] { 0, 0, 0 }), "NaN: black");
            Assert.That(new[] { rgb[6], rgb[7], rgb[8] }, Is.EqualTo(Of(0, 0.5)));
            Assert.That(() => FlowColours.Picture(flow, 2, 1), Throws.ArgumentException);
        }

        [Test]
        public void OcclusionStatesGetTheirColours()
        {
            var rgb = FlowColours.Occlusion(new byte[] { 0, 1, 2, 3 }, 2, 2);
            for (var p = 0; p < 4; p++)
                Assert.That(new[] { rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2] }, Is.EqualTo(FlowColours.StateColours[p]));
        }
    }
}
