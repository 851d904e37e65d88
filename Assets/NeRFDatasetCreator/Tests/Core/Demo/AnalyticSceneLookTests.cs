using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The two looks of the one analytic scene: the tests' layout stays one colour per object (its datasets' bytes are
    /// pinned), the demo's carries checkers a trainer can match across views, a fourth object, and points coloured by
    /// the texture. Expected cells are worked out by hand from the checker's definition.
    /// </summary>
    [TestFixture]
    public class AnalyticSceneLookTests
    {
        static AnalyticScene Layout(AnalyticLook look) => AnalyticScene.Layout(SceneNormalisation.Identity, AnalyticDataset.Centre, 0, look);

        /// <summary>The unit direction at <paramref name="fromZ"/> degrees from +Z (output world's up) and azimuth <paramref name="azimuth"/> degrees from +X.</summary>
        static Vector3d Direction(double fromZ, double azimuth)
        {
            double t = fromZ * Math.PI / 180, a = azimuth * Math.PI / 180;
            return new Vector3d(Math.Sin(t) * Math.Cos(a), Math.Sin(t) * Math.Sin(a), Math.Cos(t));
        }

        [Test]
        public void TheTestsLayoutIsUntexturedWithThreeObjects()
        {
            var scene = Layout(AnalyticLook.Test);
            Assert.That(scene.ObjectCount, Is.EqualTo(3));
            Assert.That(scene.Spheres.Select(s => s.Colour2).Concat(scene.Boxes.Select(b => b.Colour2)), Has.All.Null);
            var ball = scene.Spheres[0];
            Assert.That(AnalyticScene.ColourOf(ball, Direction(40, 100)), Is.SameAs(ball.Colour));
            Assert.That(AnalyticScene.ColourOf(ball, Direction(70, 100)), Is.SameAs(ball.Colour));
        }

        [Test]
        public void TheDemoLooksSpheresAreLatitudeLongitudeCheckers()
        {
            var ball = Layout(AnalyticLook.Demo).Spheres[0];
            Assert.That(ball.Bands, Is.EqualTo(6));
            // 40° from the pole: band ⌊40/180·6⌋ = 1; azimuth 100°: longitude 100° + 180° = 280°, sector ⌊280/360·12⌋ = 9;
            // 1 + 9 even → the first colour. 70°: band 2, 2 + 9 odd → the second.
            Assert.That(AnalyticScene.ColourOf(ball, Direction(40, 100)), Is.SameAs(ball.Colour));
            Assert.That(AnalyticScene.ColourOf(ball, Direction(70, 100)), Is.SameAs(ball.Colour2));
            // Azimuth 130°: 310°, sector ⌊10.33⌋ = 10; band 1 + 10 odd.
            Assert.That(AnalyticScene.ColourOf(ball, Direction(40, 130)), Is.SameAs(ball.Colour2));
        }

        [Test]
        public void TheDemoLooksBoxesAreCheckersOfCubesFromTheirMinimumCorner()
        {
            var scene = Layout(AnalyticLook.Demo);
            Assert.That(scene.ObjectCount, Is.EqualTo(4), "two spheres, the slab and the crate");
            var slab = scene.Boxes[0];
            Assert.That(slab.Cell, Is.EqualTo(0.2));
            // On the face z = min: cells (0, 0, 0) → even; (1, 0, 0) → odd; (1, 1, 0) → even.
            Assert.That(AnalyticScene.ColourOf(slab, slab.Min + new Vector3d(0.05, 0.05, 0)), Is.SameAs(slab.Colour));
            Assert.That(AnalyticScene.ColourOf(slab, slab.Min + new Vector3d(0.25, 0.05, 0)), Is.SameAs(slab.Colour2));
            Assert.That(AnalyticScene.ColourOf(slab, slab.Min + new Vector3d(0.25, 0.25, 0)), Is.SameAs(slab.Colour));
        }

        [Test]
        public void TheDemoLooksCrateSitsOnTheSlabAndIsTheFourthId()
        {
            var scene = Layout(AnalyticLook.Demo);
            var slab = scene.Boxes[0];
            var crate = scene.Boxes[1];
            // Output world: +Z up (Unity's y); the crate's bottom is the slab's top, its footprint inside the slab's.
            Assert.That(crate.Min.Z, Is.EqualTo(slab.Max.Z).Within(1e-12));
            Assert.That(crate.Min.X, Is.GreaterThan(slab.Min.X));
            Assert.That(crate.Max.X, Is.LessThan(slab.Max.X));
            // A ray straight down onto the crate's centre hits it (id 4: spheres 1, 2, then the slab 3 and the crate).
            var top = new Vector3d((crate.Min.X + crate.Max.X) / 2, (crate.Min.Y + crate.Max.Y) / 2, crate.Max.Z + 5);
            Assert.That(scene.Trace(top, new Vector3d(0, 0, -1), 0, out var t, out var normal, out _, out _, out var id), Is.True);
            Assert.That(id, Is.EqualTo(4));
            Assert.That(t, Is.EqualTo(5).Within(1e-9));
            Assert.That(normal.Z, Is.EqualTo(1));
            Assert.That(AnalyticDataset.LabelObjects(AnalyticLook.Demo).Length, Is.EqualTo(4));
            Assert.That(AnalyticSceneMeshes.At(0, AnalyticLook.Demo).Select(m => m.Name), Is.EqualTo(new[] { "opaque", "glass", "slab", "crate" }));
        }

        [Test]
        public void TheDemoLooksPointsCarryTheTexturesAlbedo()
        {
            var scene = Layout(AnalyticLook.Demo);
            byte[] Encoded(double[] c) => c.Select(Srgb.EncodeByteExact).ToArray();
            var colours = scene.Spheres.SelectMany(s => new[] { s.Colour, s.Colour2 }).Concat(scene.Boxes.SelectMany(b => new[] { b.Colour, b.Colour2 }))
                .Select(c => string.Join(",", Encoded(c))).ToList();
            var points = scene.Surface(2000);
            Assert.That(points.Select(p => p.Red + "," + p.Green + "," + p.Blue).Distinct(), Is.SubsetOf(colours));
            Assert.That(points.Select(p => p.Red + "," + p.Green + "," + p.Blue).Distinct().Count(), Is.EqualTo(colours.Count), "both colours of every object");
        }
    }
}
