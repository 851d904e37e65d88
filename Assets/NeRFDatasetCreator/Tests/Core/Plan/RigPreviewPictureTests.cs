using System;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class RigPreviewPictureTests
    {
        // Layout by hand from the documented constants: panels 480 px at x = 16 and x = 512, below a 28 px title
        // strip; the farthest point (extent 4 here) lands 240 − 24 = 216 px from a panel's centre, so 54 px a unit.
        const int TopCentreX = 16 + 240, SideCentreX = 16 + 480 + 16 + 240, CentreY = 28 + 240;
        const int PixelsPerUnit = 54;

        static readonly byte[] Train = { 86, 180, 233 }, Val = { 230, 159, 0 }, Test = { 204, 121, 167 };

        // OpenGL camera-to-world: columns right, up, back (−look), position.
        static Matrix4x4d Camera(Vector3d right, Vector3d up, Vector3d back, Vector3d position) => Matrix4x4d.FromColumns(right, up, back, position);

        static RgbCanvas HandMadeRig() => RigPreviewPicture.Draw(new[]
        {
            // At +X, looking at the origin (along −X) with +Z up.
            new PictureCamera(DatasetSplit.Train, Camera(Vector3d.UnitY, Vector3d.UnitZ, Vector3d.UnitX, new Vector3d(4, 0, 0))),
            new PictureCamera(DatasetSplit.Val, Camera(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ, new Vector3d(-2, 3, 1))),
            // Straight above the target, looking down.
            new PictureCamera(DatasetSplit.Test, Camera(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ, new Vector3d(0, 0, 2))),
        }, Vector3d.Zero, targetRadius: 1, sphereRadius: 0);

        [Test]
        public void CamerasAppearInTheirSplitColourWhereTheTopAndSideViewsPutThem()
        {
            var canvas = HandMadeRig();
            Assert.That(canvas.Width, Is.EqualTo(1008));
            Assert.That(canvas.Height, Is.EqualTo(540));
            // Top view: x right, y up.
            Assert.That(canvas.Get(TopCentreX + 4 * PixelsPerUnit, CentreY), Is.EqualTo(Train));
            Assert.That(canvas.Get(TopCentreX - 2 * PixelsPerUnit, CentreY - 3 * PixelsPerUnit), Is.EqualTo(Val));
            Assert.That(canvas.Get(TopCentreX, CentreY), Is.EqualTo(Test), "the camera above the target covers its cross");
            // Side view: x right, z up.
            Assert.That(canvas.Get(SideCentreX + 4 * PixelsPerUnit, CentreY), Is.EqualTo(Train));
            Assert.That(canvas.Get(SideCentreX - 2 * PixelsPerUnit, CentreY - 1 * PixelsPerUnit), Is.EqualTo(Val));
            Assert.That(canvas.Get(SideCentreX, CentreY - 2 * PixelsPerUnit), Is.EqualTo(Test));
        }

        [Test]
        public void TheTickPointsAlongTheViewingDirection()
        {
            var canvas = HandMadeRig();
            // The train camera looks along −X: its tick runs left of its disc, nothing of it to the right.
            Assert.That(canvas.Get(TopCentreX + 4 * PixelsPerUnit - 12, CentreY), Is.EqualTo(Train));
            Assert.That(canvas.Get(TopCentreX + 4 * PixelsPerUnit + 12, CentreY), Is.Not.EqualTo(Train));
            // The test camera looks straight down: in the side view its tick runs down from it, in the top view it has none.
            Assert.That(canvas.Get(SideCentreX, CentreY - 2 * PixelsPerUnit + 12), Is.EqualTo(Test));
            Assert.That(canvas.Get(SideCentreX, CentreY - 2 * PixelsPerUnit - 12), Is.Not.EqualTo(Test));
            Assert.That(canvas.Get(TopCentreX + 10, CentreY), Is.Not.EqualTo(Test));
        }

        [Test]
        public void TheTargetSphereIsFilledAndTheRestIsPanel()
        {
            var canvas = HandMadeRig();
            Assert.That(canvas.Get(TopCentreX + 30, CentreY + 30), Is.EqualTo(RigPreviewPicture.TargetFill), "radius 1 = 54 px");
            Assert.That(canvas.Get(SideCentreX - 30, CentreY + 30), Is.EqualTo(RigPreviewPicture.TargetFill));
            Assert.That(canvas.Get(TopCentreX + 80, CentreY + 80), Is.EqualTo(RigPreviewPicture.PanelBackground), "113 px out, off the 54 px grid");
            Assert.That(canvas.Get(4, 300), Is.EqualTo(RigPreviewPicture.Background), "the gap left of the top panel");
        }

        [Test]
        public void APlansCamerasLandOnTheFormationSphere()
        {
            // A ring at the equator, distance 4, normalisation none: the four train cameras lie on the dotted
            // sphere, which is then the extent: 216 px = 4 units.
            var s = new DatasetSettings { Normalisation = NormalisationMode.None, Distance = 4 };
            s.Train.Count = 4;
            s.Train.Formation = new FormationSettings { Kind = FormationKind.Orbit, Turns = 1, LowElevationDegrees = 0, HighElevationDegrees = 0 };
            s.Val.Count = 1;
            s.Test.Count = 1;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            var canvas = RigPreviewPicture.Draw(plan);
            var train = plan.ViewsOf(DatasetSplit.Train).ToList();
            Assert.That(train.Select(v => v.TransformMatrix.Translation.Z), Is.All.EqualTo(0).Within(1e-9));
            foreach (var v in train)
            {
                var p = v.TransformMatrix.Translation;
                Assert.That(p.X * p.X + p.Y * p.Y, Is.EqualTo(16).Within(1e-9));
                var pixel = RigPreviewPicture.TopPixel(p, Vector3d.Zero, PixelsPerUnit);
                Assert.That(pixel[0], Is.EqualTo(TopCentreX + p.X * PixelsPerUnit).Within(1e-9));
                Assert.That(pixel[1], Is.EqualTo(CentreY - p.Y * PixelsPerUnit).Within(1e-9));
                Assert.That(canvas.Get((int)pixel[0], (int)pixel[1]), Is.EqualTo(Train), "train " + v.Index + " at " + p);
            }
        }

        [Test]
        public void EncodesAnRgbPngOfTheCanvas()
        {
            var s = new DatasetSettings();
            s.Train.Count = 5;
            s.Val.Count = 2;
            s.Test.Count = 3;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            var png = ReferencePngDecoder.Decode(RigPreviewPicture.Encode(plan));
            Assert.That(png.Width, Is.EqualTo(RigPreviewPicture.Width));
            Assert.That(png.Height, Is.EqualTo(RigPreviewPicture.Height));
            Assert.That(png.ColorType, Is.EqualTo(2), "truecolour, opaque");
            Assert.That(png.BitDepth, Is.EqualTo(8));
            Assert.That(png.Pixels, Is.EqualTo(RigPreviewPicture.Draw(plan).Pixels));
        }

        static bool Near(RgbCanvas canvas, double x, double y, byte[] colour)
        {
            for (var dy = -1; dy <= 1; dy++)
                for (var dx = -1; dx <= 1; dx++)
                    if (canvas.Get((int)Math.Floor(x) + dx, (int)Math.Floor(y) + dy).SequenceEqual(colour)) return true;
            return false;
        }

        [Test]
        public void AVolumeBoxIsDrawnAsItsProjectedEdgesInItsSplitColour()
        {
            // A Unity box 4 wide (x), 2 high (y), 2 deep (z), centred at y = 1 and turned 90° about Unity's up: its
            // long side runs along Unity z. Output = (x, z, y)_Unity: X ±1, Y ±2, Z 0..2. Its reach (2) is the
            // extent, so 216 / 2 = 108 px a unit.
            var box = new OrientedBox("Volume", new Vector3d(0, 1, 0), Quaterniond.AngleAxis(90, Vector3d.UnitY), new Vector3d(4, 2, 2));
            var picture = PictureBox.FromUnity(DatasetSplit.Train, box, SceneNormalisation.Identity);
            Assert.That(picture.Corners.Select(c => Math.Abs(c.X)), Is.All.EqualTo(1).Within(1e-12));
            Assert.That(picture.Corners.Select(c => Math.Abs(c.Y)), Is.All.EqualTo(2).Within(1e-12));
            Assert.That(picture.Corners.Select(c => c.Z).Distinct().OrderBy(z => Math.Round(z, 9)).Select(z => Math.Round(z, 9)).Distinct(), Is.EqualTo(new[] { 0.0, 2.0 }));
            Assert.That(PictureBox.Edges, Has.Length.EqualTo(12));

            var canvas = RigPreviewPicture.Draw(new PictureCamera[0], Vector3d.Zero, 0, 0, new[] { picture });
            const int ppu = 108;
            // Top view: a 2 × 4 rectangle, corners at (±108, ±216) px from the centre; its sides' midpoints too.
            foreach (var sx in new[] { -1, 1 })
                foreach (var sy in new[] { -1, 1 })
                    Assert.That(Near(canvas, TopCentreX + sx * ppu, CentreY - sy * 2 * ppu, Train), Is.True, "top corner " + sx + ", " + sy);
            Assert.That(Near(canvas, TopCentreX + ppu, CentreY, Train), Is.True, "the X = +1 side");
            Assert.That(Near(canvas, TopCentreX, CentreY - 2 * ppu, Train), Is.True, "the Y = +2 side");
            // Side view (X right, Z up): a 2 × 2 square from the ground up.
            Assert.That(Near(canvas, SideCentreX - ppu, CentreY, Train), Is.True);
            Assert.That(Near(canvas, SideCentreX + ppu, CentreY - 2 * ppu, Train), Is.True);
            Assert.That(Near(canvas, SideCentreX, CentreY - 2 * ppu, Train), Is.True, "the top edge");
            // Inside and outside the outline: no box colour.
            Assert.That(canvas.Get(TopCentreX + 50, CentreY + 100), Is.Not.EqualTo(Train));
            Assert.That(canvas.Get(TopCentreX + 160, CentreY + 30), Is.EqualTo(RigPreviewPicture.PanelBackground), "beyond X = +1");
            Assert.That(canvas.Get(SideCentreX + 50, CentreY - 100), Is.Not.EqualTo(Train));
            Assert.That(canvas.Get(SideCentreX + 50, CentreY + 50), Is.EqualTo(RigPreviewPicture.PanelBackground), "below the ground");
        }

        [Test]
        public void AnOrientedBoxShowsItsTurnedOutline()
        {
            // A 2-unit cube turned 45° about Unity's up: from above a diamond with corners at X = ±√2 and Y = ±√2.
            var box = new OrientedBox("Volume", Vector3d.Zero, Quaterniond.AngleAxis(45, Vector3d.UnitY), new Vector3d(2, 2, 2));
            var canvas = RigPreviewPicture.Draw(new PictureCamera[0], Vector3d.Zero, 0, 0,
                new[] { PictureBox.FromUnity(DatasetSplit.Test, box, SceneNormalisation.Identity) });
            const double half = 216; // the reach √2 is the extent
            Assert.That(Near(canvas, TopCentreX + half, CentreY, Test), Is.True);
            Assert.That(Near(canvas, TopCentreX - half, CentreY, Test), Is.True);
            Assert.That(Near(canvas, TopCentreX, CentreY - half, Test), Is.True);
            Assert.That(Near(canvas, TopCentreX + half / 2, CentreY - half / 2, Test), Is.True, "the diamond's side");
            Assert.That(canvas.Get(TopCentreX + 180, CentreY - 180), Is.EqualTo(RigPreviewPicture.PanelBackground), "outside the diamond: an axis-aligned box would be there");
            // From the front: X ±√2, Z ±1 — the outline, and the near vertical edge down the middle.
            Assert.That(Near(canvas, SideCentreX + half, CentreY - half / Math.Sqrt(2), Test), Is.True);
            Assert.That(Near(canvas, SideCentreX, CentreY + 100, Test), Is.True, "the edge at X = 0");
        }

        [Test]
        public void APlanWithAVolumeDrawsItsBoxesAndNoTargetSphere()
        {
            // Unity room centred at y = 1, 10 × 2 × 10: output X ±5, Y ±5, Z 0..2; reach 5, so 43.2 px a unit.
            var room = OrientedBox.AxisAligned("Room", new Vector3d(0, 1, 0), new Vector3d(10, 2, 10));
            var nook = OrientedBox.AxisAligned("Nook", new Vector3d(-3, 1, -3), new Vector3d(1, 1, 1));
            var s = new DatasetSettings { Normalisation = NormalisationMode.None, Width = 200, Height = 100, Seed = 3 };
            s.Train.Count = 20;
            s.Train.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "Room", Volume = new VolumeScene(room, null) };
            s.Val.Count = 1;
            s.Val.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "Nook", Volume = new VolumeScene(nook, null) };
            s.Test.Count = 1;
            s.Test.Source = new CameraSourceSettings { Kind = CameraSourceKind.Volume, ObjectPath = "Nook", Volume = new VolumeScene(nook, null) };
            var plan = CapturePlan.Build(s, new PlanTarget(Vector3d.Zero, 1));
            Assert.That(RigPreviewPicture.VolumeBoxes(plan).Select(b => b.Split), Is.EqualTo(new[] { DatasetSplit.Train, DatasetSplit.Val, DatasetSplit.Test }));
            var canvas = RigPreviewPicture.Draw(plan);
            Assert.That(Near(canvas, TopCentreX + 216, CentreY - 216, Train), Is.True, "room corner (5, 5)");
            Assert.That(Near(canvas, TopCentreX - 216, CentreY + 216, Train), Is.True, "room corner (−5, −5)");
            Assert.That(Near(canvas, SideCentreX + 216, CentreY - 2 * 43.2, Train), Is.True, "room corner X 5, Z 2");
            // The nook: output X −3.5..−2.5, Y −3.5..−2.5; the test box is drawn over the val box.
            // Cameras are drawn over the boxes: most of the nook's outline, not every pixel, is the test colour.
            var onOutline = 0;
            for (var k = 0; k <= 40; k++)
            {
                var t = -3.5 + k / 40.0;
                foreach (var p in new[] { new Vector3d(t, -3.5, 0), new Vector3d(t, -2.5, 0), new Vector3d(-3.5, t, 0), new Vector3d(-2.5, t, 0) })
                {
                    var px = RigPreviewPicture.TopPixel(p, Vector3d.Zero, 43.2);
                    if (Near(canvas, px[0], px[1], Test)) onOutline++;
                }
            }
            Assert.That(onOutline, Is.GreaterThan(0.8 * 164), "test box outline pixels");
            var fills = 0;
            for (var y = 0; y < canvas.Height; y++)
                for (var x = 0; x < canvas.Width; x++)
                    if (canvas.Get(x, y).SequenceEqual(RigPreviewPicture.TargetFill)) fills++;
            Assert.That(fills, Is.EqualTo(0), "an environment's root is not drawn as a sphere");
        }

        [TestCase(4, 1)]
        [TestCase(0.3, 0.1)]
        [TestCase(1000, 500)]
        [TestCase(7, 2)]
        public void GridStepsAreOneTwoOrFiveTimesAPowerOfTen(double extent, double step) =>
            Assert.That(RigPreviewPicture.GridStep(extent), Is.EqualTo(step).Within(1e-12));

        [Test]
        public void TextUsesTheFivebySevenGlyphs()
        {
            var canvas = new RgbCanvas(20, 10, new byte[] { 0, 0, 0 });
            var white = new byte[] { 255, 255, 255 };
            Assert.That(canvas.Text(0, 0, "t", white, scale: 1), Is.EqualTo(6));
            // T: a full top row, then only the middle column.
            Assert.That(Enumerable.Range(0, 5).Select(x => canvas.Get(x, 0)[0]), Is.All.EqualTo(255));
            Assert.That(canvas.Get(2, 6)[0], Is.EqualTo(255));
            Assert.That(canvas.Get(1, 6)[0], Is.EqualTo(0));
            Assert.That(canvas.Get(5, 0)[0], Is.EqualTo(0), "the blank column between glyphs");
        }
    }
}
