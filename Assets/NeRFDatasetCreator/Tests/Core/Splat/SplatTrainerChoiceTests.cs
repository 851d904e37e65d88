using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SplatTrainerChoiceTests
    {
        [Test]
        public void AutoDetectsAndTheOthersAreTheTrainersName()
        {
            Assert.That(SplatTrainerChoice.Argument(0), Is.Null);
            Assert.That(SplatTrainerChoice.Argument(1), Is.EqualTo("3dgs"));
            Assert.That(SplatTrainerChoice.Argument(2), Is.EqualTo("nerfstudio"));
            Assert.That(SplatTrainerChoice.Argument(3), Is.EqualTo("gsplat"));
            Assert.Throws<ArgumentOutOfRangeException>(() => SplatTrainerChoice.Argument(4));
        }

        [Test]
        public void APlacementIsShownWithEveryNumberExact()
        {
            var p = new SplatPlacement("3dgs", "/m/point_cloud/iteration_30000/point_cloud.ply",
                new double[] { 0.5, 0, 0, 1, 0, 0, 0.5, 3, 0, 0.5, 0, 2, 0, 0, 0, 1 },
                new double[] { 1, 3, 2 }, new[] { Math.Sqrt(0.5), 0, 0, Math.Sqrt(0.5) }, new[] { 0.5, 0.5, -0.5 }, null, new[] { "A note." });
            var lines = SplatTrainerChoice.Describe(p);
            Assert.That(lines[0], Is.EqualTo("Trainer: 3dgs"));
            Assert.That(lines[2], Is.EqualTo("Position: (1, 3, 2)"));
            Assert.That(lines[3], Is.EqualTo("Rotation (quaternion x, y, z, w): (0.7071067811865476, 0, 0, 0.7071067811865476)"));
            Assert.That(lines[4], Is.EqualTo("Scale: (0.5, 0.5, -0.5)"));
            Assert.That(lines[7], Is.EqualTo("  (0, 0, 0.5, 3)"), "row 1");
            Assert.That(lines[10], Is.EqualTo("cameras.json: not written"));
            Assert.That(lines[11], Is.EqualTo("A note."));
        }
    }
}
