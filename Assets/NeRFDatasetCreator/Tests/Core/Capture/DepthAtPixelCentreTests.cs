using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The independent expectation behind the depth bytes <see cref="ViewPipelineBytesTests"/> pins for data passes at the
    /// supersampled size (issue 32 item 19): each written depth pixel holds the analytic z-depth AT ITS PIXEL CENTRE —
    /// traced through the written lens's distorted pixel, not through the capture's wide render — not the depth a quarter
    /// pixel off it, where the lower-left central sample lies (the rule before: one point sample of the 2×2 block).
    /// </summary>
    [TestFixture]
    public class DepthAtPixelCentreTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        sealed class Traced
        {
            public PlannedView View;
            public AnalyticScene Scene;
            public AnalyticDataset.RayOf Rays;
        }

        static bool Z(Traced traced, double i, double j, out double z, out int id)
        {
            traced.Rays(i, j, out var o, out var d);
            var hit = traced.Scene.Trace(o, d, 0, out z, out _, out _, out _, out id);
            return hit;
        }

        [TestCase(true, TestName = "DepthAtPixelCentre_LensSupersampledData")]
        [TestCase(false, TestName = "DepthAtPixelCentre_PinholeSupersampledData")]
        public void SupersampledDepthHoldsTheDepthAtThePixelCentre(bool lens)
        {
            var traced = new List<Traced>();
            // The lens case is ViewPipelineBytesTests' "lens-blur-shared" (lens through the wide render, labels, exposure,
            // blur; depth at the supersampled size): the very files whose sums it pins.
            var options = lens ? ViewPipelineBytesTests.Options(lens: true, dataAtOutputSize: false, blur: true)
                : new AnalyticDataset.Options { Width = 48, Height = 36, Supersampling = 2, Train = 2, Val = 1, Test = 1, PointCloud = 0, DataAtOutputSize = false };
            options.OutputRays = (view, scene, rays) => traced.Add(new Traced { View = view, Scene = scene, Rays = rays });
            var name = lens ? "lens-blur-shared" : "pinhole";
            var folder = AnalyticDataset.Write(_temp.Path, name, options);
            if (lens)
            {
                var depthSums = ViewPipelineBytesTests.Sums(folder).Where(p => p.Key.EndsWith("_depth_0000.png", StringComparison.Ordinal)).ToList();
                Assert.That(depthSums.Count, Is.EqualTo(4));
                foreach (var sum in depthSums) Assert.That(sum.Value, Is.EqualTo(ViewPipelineBytesTests.Expected[name + "/" + sum.Key]), "the pinned sum of " + sum.Key);
            }
            var atCentre = new List<double>();
            var offCentre = new List<double>();
            foreach (var t in traced)
            {
                var path = Path.Combine(folder, DatasetLayout.RelativePath(t.View.Split, t.View.Index, DatasetFileKind.DepthPng));
                var mm = PngGray16Reader.Read(path, out var w, out var h);
                for (var oy = 0; oy < h; oy++)
                    for (var ox = 0; ox < w; ox++)
                    {
                        // Only where the block's four samples (±¼ px) and the centre see one smooth surface: across an
                        // edge the pixel takes the nearest surface by design.
                        if (!Z(t, ox + 0.5, oy + 0.5, out var centre, out var id)) continue;
                        var same = true;
                        double offset = 0;
                        foreach (var (di, dj) in new[] { (0.25, 0.75), (0.75, 0.75), (0.25, 0.25), (0.75, 0.25) })
                        {
                            same &= Z(t, ox + di, oy + dj, out var z, out var other) && other == id && Math.Abs(z - centre) < 0.01 * centre;
                            if (di == 0.25 && dj == 0.75) offset = z; // the lower-left sample: the block's first in PointSampling order
                        }
                        var written = mm[oy * w + ox] / 1000.0;
                        if (!same || written == 0) continue;
                        atCentre.Add(Math.Abs(written - centre) * 1000);
                        offCentre.Add(Math.Abs(written - offset) * 1000);
                    }
            }
            var medianAt = CheckFigures.Median(atCentre);
            var medianOff = CheckFigures.Median(offCentre);
            var p95At = CheckFigures.Percentile(atCentre, 0.95);
            TestContext.WriteLine(atCentre.Count + " smooth pixels: |written − z(centre)| median " + medianAt.ToString("0.###") + " mm, 95th " + p95At.ToString("0.###") +
                                  " mm; |written − z(lower-left sample)| median " + medianOff.ToString("0.###") + " mm");
            Assert.That(atCentre.Count, Is.GreaterThan(500), "pixels compared");
            // 16-bit millimetres round to ±0.5 mm; the harmonic mean of a curved surface's samples and the lens's
            // resampling of the wide render's depth add a fraction of a millimetre at ~2–4 units.
            Assert.That(medianAt, Is.LessThanOrEqualTo(0.5), "median distance to the centre's depth (mm)");
            Assert.That(medianAt, Is.LessThan(medianOff / 2), "closer to the centre's depth than to the quarter-pixel-off sample's");
        }
    }
}
