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
