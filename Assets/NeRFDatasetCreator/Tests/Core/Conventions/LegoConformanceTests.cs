using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Conformance with the real nerf_synthetic data: a Unity camera placed where each lego training frame's camera
    /// is, looking at the origin, must convert to that frame's transform_matrix.
    /// </summary>
    [TestFixture]
    public class LegoConformanceTests
    {
        static JObject Lego => JObject.Parse(File.ReadAllText(Fixtures.LegoTrainPath));

        static IEnumerable<TestCaseData> Frames()
        {
            foreach (var frame in Lego["frames"])
                yield return new TestCaseData((string)frame["file_path"]).SetName("Lego frame " + (string)frame["file_path"]);
        }

        static double[][] MatrixOf(string filePath)
        {
            foreach (var frame in Lego["frames"])
                if ((string)frame["file_path"] == filePath)
                    return frame["transform_matrix"].ToObject<double[][]>();
            throw new ArgumentException(filePath);
        }

        [TestCaseSource(nameof(Frames))]
        public void UnityCameraAtTheFramesPositionLookingAtTheOriginGivesTheFramesMatrix(string filePath)
        {
            var expected = MatrixOf(filePath);
            var blenderPosition = new Vector3d(expected[0][3], expected[1][3], expected[2][3]);

            var pose = LookAt.FromPositions(BlenderConvention.ToUnity(blenderPosition), Vector3d.Zero);
            var actual = BlenderConvention.CameraToWorld(pose);

            for (var r = 0; r < 4; r++)
                for (var c = 0; c < 4; c++)
                    Assert.That(actual[r, c], Is.EqualTo(expected[r][c]).Within(1e-5), $"{filePath} [{r}][{c}]");
        }

        [Test]
        public void TheFixtureHasAllHundredTrainingFrames()
        {
            Assert.That(Lego["frames"], Has.Count.EqualTo(100));
        }

        [Test]
        public void CameraAngleXOfAnEightHundredSquareCameraWithTheLegoLensMatchesTheFile()
        {
            // Blender's default camera: a 50 mm lens on a 36 mm sensor. For a square image the vertical FOV equals
            // the horizontal one, 2·atan(18/50).
            var verticalFovDegrees = 2 * Math.Atan(18.0 / 50.0) * 180 / Math.PI;
            var intrinsics = CameraIntrinsics.FromVerticalFov(verticalFovDegrees, 800, 800);
            // The file stores Blender's float32 value, one float step from the exact angle.
            Assert.That(intrinsics.CameraAngleX, Is.EqualTo((double)Lego["camera_angle_x"]).Within(1e-7));
            Assert.That(intrinsics.FlX, Is.EqualTo(400 / 0.36).Within(1e-9));
        }
    }
}
