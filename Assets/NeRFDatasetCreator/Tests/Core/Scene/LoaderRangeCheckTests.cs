using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The §2.4 constraints by hand: near 2 / far 6 around the target's sphere, 3DGS's ±1.3 init cube.</summary>
    public class LoaderRangeCheckTests
    {
        static Vector3d[] Ring(double radius) =>
            Enumerable.Range(0, 8).Select(i => new Vector3d(radius * System.Math.Cos(i), radius * System.Math.Sin(i), 0.5)).ToArray();

        [Test]
        public void NerfSyntheticLikeScene_HasNoWarning()
        {
            Assert.That(LoaderRangeCheck.Check(Ring(4), 1.0), Is.Empty);
        }

        [Test]
        public void PresetLimit_BIs0325R_HoldsExactly()
        {
            // s = 4/R puts cameras at 4; b ≤ 0.325·R becomes s·b ≤ 1.3, and then 4 − 1.3 ≥ 2, 4 + 1.3 ≤ 6.
            const double R = 10;
            var s = 4 / R;
            var cameras = new[] { new Vector3d(0, 0, R * s) };

            Assert.That(LoaderRangeCheck.Check(cameras, 0.325 * R * s), Is.Empty);
            Assert.That(LoaderRangeCheck.Check(cameras, 0.33 * R * s).Select(p => p.Reason).ToList(), Has.Count.EqualTo(1).And.All.Contains("3DGS's random initial cloud"));
        }

        [Test]
        public void CamerasTooClose_WarnAboutNearAndSuggestThePreset()
        {
            var problems = LoaderRangeCheck.Check(Ring(2.5), 1.0);

            Assert.That(problems.Select(p => p.Reason).ToList(), Has.Count.EqualTo(1).And.All.Contains("NeRF's fixed near distance 2"));
            Assert.That(problems[0].Reason, Does.StartWith("8 of 8 cameras"));
            Assert.That(problems[0].Fix, Does.Contain("preset"));
        }

        [Test]
        public void CamerasTooFar_WarnAboutFar()
        {
            var problems = LoaderRangeCheck.Check(Ring(5.5), 1.0);

            Assert.That(problems.Select(p => p.Reason).ToList(), Has.Count.EqualTo(1).And.All.Contains("NeRF's fixed far distance 6"));
            Assert.That(problems[0].Value, Is.EqualTo("6.523"), "√(5.5² + 0.5²) + 1");
        }

        [Test]
        public void UnscaledUnityScene_GetsNearFarAndSizeWarnings()
        {
            // A 10 m building photographed from 30 m, recentred but not scaled.
            var problems = LoaderRangeCheck.Check(Ring(30), 10);

            Assert.That(problems.Select(p => p.Reason.Contains("far distance 6") ? "far" : p.Reason.Contains("initial cloud") ? "cloud" : "?"), Is.EqualTo(new[] { "far", "cloud" }));
        }
    

        [Test]
        public void ForCapture_MeasuresFromTheTarget_AndFlagsAnOffOriginTarget()
        {
            var target = new Vector3d(10, 1, -4);
            var poses = CameraRig.Place(new RandomFormation(1), 12, target, 4.0);

            // Unnormalised: distances are fine (4 ± 1) but the target sits ~10.8 from the origin.
            var raw = LoaderRangeCheck.ForCapture(poses, SceneNormalisation.Identity, target, 1.0);
            Assert.That(raw.Select(p => p.Reason).ToList(), Has.Count.EqualTo(1).And.All.Contains("3DGS's random initial cloud"));

            var recentred = SceneNormalisation.ForTarget(NormalisationMode.Recentre, target, 1.0, 4.0);
            Assert.That(LoaderRangeCheck.ForCapture(poses, recentred, target, 1.0), Is.Empty);

            // The same rig 2.5 m out needs the preset: before it, near warnings; after it, none.
            var close = CameraRig.Place(new RandomFormation(1), 12, target, 2.5);
            Assert.That(LoaderRangeCheck.ForCapture(close, recentred, target, 0.7).Select(p => p.Reason).ToList(), Has.Count.EqualTo(1).And.All.Contains("NeRF's fixed near distance 2"));
            var preset = SceneNormalisation.ForTarget(NormalisationMode.NerfSyntheticScale, target, 0.7, 2.5);
            Assert.That(LoaderRangeCheck.ForCapture(close, preset, target, 0.7), Is.Empty);
        }
    }
}
