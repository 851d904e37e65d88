using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class RelightingInUnityTests
    {
        [Test]
        public void SkyboxRotationIsTheOutputRotationWrappedIntoZeroTo360()
        {
            Assert.That(RelightingInUnity.SkyboxRotationDegrees(90), Is.EqualTo(90));
            Assert.That(RelightingInUnity.SkyboxRotationDegrees(-90), Is.EqualTo(270));
            Assert.That(RelightingInUnity.SkyboxRotationDegrees(360), Is.EqualTo(0));
        }

        /// <summary>
        /// Skybox-Panoramic.shader's RotateAroundYInDegrees moves the sky's direction t to (cos φ·x − sin φ·z, y,
        /// sin φ·x + cos φ·z) in Unity's world; in the output frame that must be Rz(θ) (counter-clockwise about +Z seen
        /// from above) with φ = SkyboxRotationDegrees(θ), for every direction and angle.
        /// </summary>
        [Test]
        public void TheSkyboxRotationOfUnityIsTheCounterClockwiseRotationAboutOutputZ()
        {
            var directions = new[] { new Vector3d(1, 0, 0), new Vector3d(0, 0, 1), new Vector3d(0.3, 0.8, -0.52), new Vector3d(-0.6, -0.2, 0.77) };
            foreach (var theta in new[] { 0.0, 30, 90, 180, 270, 359 })
            {
                var phi = RelightingInUnity.SkyboxRotationDegrees(theta) * Math.PI / 180;
                var t = theta * Math.PI / 180;
                foreach (var unity in directions)
                {
                    var movedInUnity = new Vector3d(Math.Cos(phi) * unity.X - Math.Sin(phi) * unity.Z, unity.Y, Math.Sin(phi) * unity.X + Math.Cos(phi) * unity.Z);
                    var output = BlenderConvention.FromUnity(unity);
                    var rz = new Vector3d(Math.Cos(t) * output.X - Math.Sin(t) * output.Y, Math.Sin(t) * output.X + Math.Cos(t) * output.Y, output.Z);
                    var got = BlenderConvention.FromUnity(movedInUnity);
                    Assert.That((got - rz).Length, Is.LessThan(1e-12), "θ = " + theta + ", d = " + output);
                }
            }
            // A hand example: light from output +X, turned 90° counter-clockwise, arrives from output +Y.
            var p = 90 * Math.PI / 180;
            var fromX = BlenderConvention.FromUnity(new Vector3d(Math.Cos(p), 0, Math.Sin(p)));
            Assert.That(fromX.X, Is.EqualTo(0).Within(1e-12));
            Assert.That(fromX.Y, Is.EqualTo(1).Within(1e-12));
        }

        [Test]
        public void KeysAreTheNameOrTheNameWithThreeDigitDegrees()
        {
            var sunset = new LightingCondition { Name = "sunset", Kind = LightingKind.Environment, Rotations = new double[] { 0, 90, 270 } };
            var olat = new LightingCondition { Name = "olat-03", Kind = LightingKind.Point };
            var renders = RelightingInUnity.Resolve(new RelightingSettings { On = true, Conditions = new List<LightingCondition> { sunset, olat } }, SceneNormalisation.Identity);
            Assert.That(renders.ConvertAll(r => r.Key), Is.EqualTo(new[] { "sunset_000", "sunset_090", "sunset_270", "olat-03" }));
            Assert.That(RelightingInUnity.Resolve(new RelightingSettings(), SceneNormalisation.Identity), Is.Empty, "off: no renders");
        }

        [Test]
        public void PositionsAndDirectionsGoBackThroughTheDatasetsUnityFrame()
        {
            // x_out = s·(B·x_unity − c) with s = 0.5, c = (1, 2, 3): x_unity = B(x_out / s + c).
            var normalisation = new SceneNormalisation(new Vector3d(1, 2, 3), 0.5);
            var spot = new LightingCondition { Name = "key", Kind = LightingKind.Spot, Position = new double[] { 0, -3, 3 }, Direction = null };
            var render = RelightingInUnity.Resolve(new RelightingSettings { On = true, Conditions = new List<LightingCondition> { spot } }, normalisation)[0];
            // (0, −3, 3)/0.5 + (1, 2, 3) = (1, −4, 9) → Unity (1, 9, −4).
            Assert.That((render.Position - new Vector3d(1, 9, -4)).Length, Is.LessThan(1e-12));
            // Default direction: towards the output origin, −(0, −3, 3) = (0, 3, −3) → Unity (0, −3, 3), unit.
            var s = 1 / Math.Sqrt(2);
            Assert.That((render.Direction - new Vector3d(0, -s, s)).Length, Is.LessThan(1e-12));
            // And the point the direction aims at is the output origin's Unity position B(c) = (1, 3, 2).
            var towardsOrigin = new Vector3d(1, 3, 2) - render.Position;
            Assert.That((towardsOrigin / towardsOrigin.Length - render.Direction).Length, Is.LessThan(1e-12));
        }
    }
}
