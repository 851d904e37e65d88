using System;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// An inside-out capture keeps nerfstudio's scene contraction and lets nerfstudio-data centre on the mean camera and
    /// scale the cameras into ±1 (nerfstudio_dataparser.py 243–249: scale = 1 / max |coordinate| of the centred
    /// camera positions). Expected values worked by hand.
    /// </summary>
    public class NerfstudioEnvironmentTrainingTests
    {
        // Mean (2, 0, 1); centred: (−2, 0, 0), (2, 0, 0), (0, 1, −1), (0, −1, 1): largest |coordinate| 2.
        static readonly Vector3d[] Cameras = { new Vector3d(0, 0, 1), new Vector3d(4, 0, 1), new Vector3d(2, 1, 0), new Vector3d(2, -1, 2) };

        [Test]
        public void AutoScaleIsOneOverTheLargestCentredCoordinate()
        {
            Assert.That(NerfstudioTraining.AutoScale(Cameras), Is.EqualTo(0.5));
            Assert.That(NerfstudioTraining.AutoScale(new[] { new Vector3d(3, 3, 3) }), Is.EqualTo(1), "one camera: nothing to scale by");
        }

        [TestCase(20.0, 12.0)]  // (20 + |(2, 0, 1)| = 22.236) · 0.5 = 11.118 → 12 (2 significant digits, up)
        [TestCase(100.0, 52.0)] // 102.236 · 0.5 = 51.118 → 52
        [TestCase(0.5, 1.4)]    // 2.736 · 0.5 = 1.368 → 1.4
        public void InstantNgpsSceneBoxHoldsTheEnvironmentAfterTheDataparsersScaling(double reach, double expected)
        {
            var scale = NerfstudioTraining.EnvironmentSceneScale(Cameras, reach);
            var scaledReach = (reach + Math.Sqrt(5)) * 0.5;
            Assert.That(scale, Is.GreaterThanOrEqualTo(scaledReach));
            Assert.That(scale, Is.EqualTo(expected).Within(1e-12));
        }

        [Test]
        public void UnknownReachKeepsNerfstudiosBox() =>
            Assert.That(NerfstudioTraining.EnvironmentSceneScale(Cameras, null), Is.EqualTo(1));

        [Test]
        public void EnvironmentCommandsKeepTheContractionAndCentreOnTheCameras()
        {
            Assert.That(NerfstudioTraining.EnvironmentCommands("/d/transforms.json", Cameras, 20), Is.EqualTo(new[]
            {
                "ns-train nerfacto --pipeline.model.disable-scene-contraction False --data /d/transforms.json nerfstudio-data --orientation-method none --center-method poses --auto-scale-poses True",
                "ns-train splatfacto --data /d/transforms.json nerfstudio-data --orientation-method none --center-method poses --auto-scale-poses True",
                "ns-train instant-ngp --pipeline.model.disable-scene-contraction False --data /d/transforms.json nerfstudio-data --orientation-method none --center-method poses --auto-scale-poses True --scene-scale 12",
            }));
        }

        [Test]
        public void TheConfigSaysWhetherASplitSampledAVolume()
        {
            JObject Config(string kind) => JObject.Parse("{\"settings\": {\"splits\": {\"train\": {\"count\": 3}, \"test\": {\"source\": {\"kind\": \"" + kind + "\"}}}}}");
            Assert.That(InsideOutRecord.FromConfig(Config("volume")), Is.True);
            Assert.That(InsideOutRecord.FromConfig(Config("sceneCameras")), Is.False);
            Assert.That(InsideOutRecord.FromConfig(JObject.Parse("{\"target\": {}}")), Is.False, "nothing recorded: an object dataset");
            Assert.That(InsideOutRecord.FromConfig(JObject.Parse("{\"settings\": {\"splits\": {\"train\": {\"source\": {\"kind\": 3}}}}}")), Is.False);
        }
    }
}
