using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The flags must leave the target inside ±1 after nerfstudio-data's own scaling: with
    /// <c>--auto-scale-poses False</c> the dataparser multiplies poses by <c>scale_factor</c> alone
    /// (nerfstudio_dataparser.py lines 244–249: <c>scale_factor = 1.0</c>, no division, <c>*= self.config.scale_factor</c>),
    /// and nerfacto's L∞ contraction keeps |x|∞ ≤ 1 unchanged (spatial_distortions.py: <c>torch.where(mag &lt; 1, x, …)</c>).
    /// Expected factors worked by hand: 1/reach rounded down to 3 significant digits.
    /// </summary>
    public class NerfstudioTrainingTests
    {
        [TestCase(0.8, 1.0)]     // already inside: no --scale-factor
        [TestCase(1.0, 1.0)]
        [TestCase(1.3, 0.769)]   // 1/1.3 = 0.76923…
        [TestCase(1.5, 0.666)]   // 0.66666…
        [TestCase(2.5, 0.4)]
        [TestCase(12.0, 0.0833)] // 0.083333…
        [TestCase(700.0, 0.00142)]
        public void ScaleFactor_IsOneOverTheReachRoundedDown(double reach, double expected)
        {
            var f = NerfstudioTraining.ScaleFactor(reach);
            Assert.That(f, Is.EqualTo(expected).Within(1e-12));
            // What nerfstudio then does to the target's farthest point (auto_scale_poses False: × scale_factor only).
            Assert.That(reach * f, Is.LessThanOrEqualTo(1.0));
        }

        [Test]
        public void UnknownReach_CountsAsNerfSyntheticsBox() =>
            Assert.That(NerfstudioTraining.ScaleFactor(null), Is.EqualTo(0.666).Within(1e-12));

        [Test]
        public void FlagsPerModelFamily()
        {
            Assert.That(NerfstudioTraining.Flags("nerfacto", 1.3),
                Is.EqualTo("--orientation-method none --center-method none --auto-scale-poses False --scale-factor 0.769"));
            Assert.That(NerfstudioTraining.Flags("instant-ngp", 0.9),
                Is.EqualTo("--orientation-method none --center-method none --auto-scale-poses False"));
            Assert.That(NerfstudioTraining.Flags("splatfacto", 1.3),
                Is.EqualTo("--orientation-method none --center-method none"), "splatfacto keeps nerfstudio's auto-scale");
            Assert.Throws<ArgumentOutOfRangeException>(() => NerfstudioTraining.Flags("vanilla-nerf", 1));
        }

        [Test]
        public void Commands_PutTheDataparserFlagsAfterTheSubcommand()
        {
            var lines = NerfstudioTraining.Commands("/data/my set/transforms.json", 2.5);
            Assert.That(lines, Is.EqualTo(new[]
            {
                "ns-train nerfacto --data \"/data/my set/transforms.json\" nerfstudio-data --orientation-method none --center-method none --auto-scale-poses False --scale-factor 0.4",
                "ns-train splatfacto --data \"/data/my set/transforms.json\" nerfstudio-data --orientation-method none --center-method none",
                "ns-train instant-ngp --data \"/data/my set/transforms.json\" nerfstudio-data --orientation-method none --center-method none --auto-scale-poses False --scale-factor 0.4",
            }));
        }
    }
}
