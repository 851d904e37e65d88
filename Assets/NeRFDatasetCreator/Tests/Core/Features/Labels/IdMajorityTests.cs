using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class IdMajorityTests
    {
        static ushort Block(params ushort[] ids) => IdMajority.Majority(ids, ids.Length);

        [Test]
        public void APixelTakesTheIdCoveringMostOfItsSamples()
        {
            Assert.That(Block(7, 7, 7, 7), Is.EqualTo(7));
            Assert.That(Block(7, 7, 5, 0), Is.EqualTo(7));
            Assert.That(Block(5, 7, 7, 7), Is.EqualTo(7));
            Assert.That(Block(3, 3, 3, 9, 9, 1, 1, 1, 1), Is.EqualTo(1));
        }

        [Test]
        public void APixelIsForegroundWhenAtLeastHalfItsSamplesHitAnObjectAsTheMaskReads128()
        {
            Assert.That(Block(5, 0, 0, 0), Is.EqualTo(0), "1 of 4: the mask reads 64");
            Assert.That(Block(5, 5, 0, 0), Is.EqualTo(5), "2 of 4: the mask reads 128");
            // Two objects share the covered half: still foreground, though the background has the most samples.
            Assert.That(Block(5, 9, 0, 0), Is.EqualTo(5));
            Assert.That(Block(4, 4, 4, 4, 0, 0, 0, 0, 0), Is.EqualTo(0), "4 of 9: the mask reads 113");
            Assert.That(Block(4, 4, 4, 4, 4, 0, 0, 0, 0), Is.EqualTo(4), "5 of 9: the mask reads 142");
        }

        [Test]
        public void ATieGoesToTheSmallerIdNeverToABlend()
        {
            Assert.That(Block(9, 5, 5, 9), Is.EqualTo(5));
            Assert.That(Block(9, 5, 0, 9, 5, 0, 0, 2, 2, 2, 9, 5, 0, 0, 0, 0), Is.EqualTo(2), "4×4: ids 9, 5 and 2 with 3 samples each, 7 background");
            Assert.That(Block(200, 100), Is.EqualTo(100));
        }

        [Test]
        public void ResolveDownsamplesBottomUpSamplesIntoTopRowFirstIdsAndMapsClasses()
        {
            // 4×2 samples at supersampling 2 → 2×1 output; rows bottom-up.
            var frame = new RawFrame(4, 4, 2)
            {
                InstanceIds = new ushort[]
                {
                    1, 1, 2, 0, // bottom row (output row 1)
                    1, 0, 2, 0,
                    3, 3, 0, 0, // top rows (output row 0)
                    3, 4, 4, 4,
                },
            };
            var ids = new ushort[4];
            IdMajority.Resolve(frame, ids);
            Assert.That(ids, Is.EqualTo(new ushort[] { 3, 4, 1, 2 }));
            // Instances 1 and 2 are class 1, 3 is class 2, 4 has no class: the semantic map counts classes, not instances.
            IdMajority.Resolve(frame, ids, new ushort[] { 0, 1, 1, 2, 0 });
            Assert.That(ids, Is.EqualTo(new ushort[] { 2, 0, 1, 1 }));
        }

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        public void ResolveAppliesTheRuleToEveryBlockAtEverySupersampling(int k)
        {
            // Random ids 0–4 in 7×5 output pixels: every block's output is Majority of its samples, whichever path ran.
            int ow = 7, oh = 5, w = ow * k, h = oh * k;
            var random = new System.Random(k);
            var frame = new RawFrame(w, h, k) { InstanceIds = new ushort[w * h] };
            for (var i = 0; i < frame.InstanceIds.Length; i++) frame.InstanceIds[i] = (ushort)(random.Next(3) == 0 ? 0 : random.Next(1, 5));
            var lookup = new ushort[] { 0, 2, 1, 2 }; // id 4 lies beyond the lookup: class 0
            var ids = new ushort[ow * oh];
            var classes = new ushort[ow * oh];
            IdMajority.Resolve(frame, ids);
            IdMajority.Resolve(frame, classes, lookup);
            for (var oy = 0; oy < oh; oy++)
                for (var ox = 0; ox < ow; ox++)
                {
                    var block = new ushort[k * k];
                    var mapped = new ushort[k * k];
                    var n = 0;
                    for (var dy = 0; dy < k; dy++)
                        for (var dx = 0; dx < k; dx++, n++)
                        {
                            // Output row oy (top first) is rendered rows (oh − 1 − oy)·k … (bottom row first).
                            block[n] = frame.InstanceIds[((oh - 1 - oy) * k + dy) * w + ox * k + dx];
                            mapped[n] = block[n] < lookup.Length ? lookup[block[n]] : (ushort)0;
                        }
                    Assert.That(ids[oy * ow + ox], Is.EqualTo(IdMajority.Majority(block, n)), "instance " + ox + "," + oy);
                    Assert.That(classes[oy * ow + ox], Is.EqualTo(IdMajority.Majority(mapped, n)), "class " + ox + "," + oy);
                }
        }

        [Test]
        public void ResolveRefusesAFrameWithoutTheIdPassNamingTheField()
        {
            var e = Assert.Throws<InvalidParameterException>(() => IdMajority.Resolve(new RawFrame(2, 2, 1), new ushort[4]));
            Assert.That(e.Message, Does.Contain("frame.InstanceIds"));
        }
    }
}
