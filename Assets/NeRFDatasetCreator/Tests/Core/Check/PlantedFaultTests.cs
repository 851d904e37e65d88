using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Each capture bug of issue 21, planted in a copy of an analytically rendered dataset, is caught by the check that
    /// should catch it (and the clean original passes: <see cref="CleanDatasetCheckTests"/>).
    /// </summary>
    [TestFixture]
    public class PlantedFaultTests
    {
        TempFolder _temp;
        string _clean;
        int _copies;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _clean = AnalyticDataset.Write(_temp.Path, "clean", new AnalyticDataset.Options());
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        string Copy() => DatasetFaults.Copy(_clean, _temp.Combine("fault-" + ++_copies));

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12)));
            return report;
        }

        static void AssertCaughtBy(DatasetCheckReport report, string check)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(20));
            Assert.That(report.Failed, Is.True, text);
            Assert.That(report.Results.Single(r => r.Name == check).Status, Is.EqualTo(DatasetCheckStatus.Failed), check + "\n" + text);
            Assert.That(report.Problems.Any(p => p.Check == check && p.Frame >= 0 && p.File.StartsWith("./", StringComparison.Ordinal)), Is.True, text);
        }

        [Test]
        public void MaskFlippedAgainstColourIsCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsMask, (png, s, _) => DatasetFaults.FlipRows(png, s));
            var report = Check(folder);
            AssertCaughtBy(report, "alpha vs mask");
            AssertCaughtBy(report, "depth vs mask");
        }

        [Test]
        public void MaskAndDepthFlippedAgainstColourAreCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, f => DatasetFaults.IsMask(f) || DatasetFaults.IsDepth(f), (png, s, _) => DatasetFaults.FlipRows(png, s));
            var report = Check(folder);
            AssertCaughtBy(report, "alpha vs mask");
            AssertCaughtBy(report, "multi-view geometry");
        }

        [Test]
        public void DepthInCentimetresIsCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsDepth, (png, s, _) => DatasetFaults.ScaleDepth(s, 0.1));
            AssertCaughtBy(Check(folder), "multi-view geometry");
        }

        [Test]
        public void DepthInTenthsOfThousandthsIsCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsDepth, (png, s, _) => DatasetFaults.ScaleDepth(s, 10));
            AssertCaughtBy(Check(folder), "multi-view geometry");
        }

        [Test]
        public void DepthAlongTheRayIsCaught()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "ray", new AnalyticDataset.Options { DepthAlongRay = true });
            var report = Check(folder);
            AssertCaughtBy(report, "depth vs normals");
            AssertCaughtBy(report, "multi-view geometry");
        }

        [Test]
        public void PoseWithoutTheYzSwapIsCaught()
        {
            // The writer forgot P: M = P₄·C became C, Unity's left-handed camera-to-world (P is its own inverse).
            var swap = Matrix4x4d.FromRowMajor(1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1);
            var folder = Copy();
            DatasetFaults.EditPoses(folder, m => swap * m);
            var report = Check(folder);
            AssertCaughtBy(report, "depth vs normals");
            AssertCaughtBy(report, "point cloud vs masks");
            Assert.That(report.Problems.Any(p => p.Check == "dataset" && p.Message.Contains("handedness")), Is.True);
        }

        [Test]
        public void CameraAxisSignFlipIsCaught()
        {
            // Unity's camera looks along +Z: forgetting OpenGL's −Z (and keeping the rotation proper by negating Y too).
            var flip = Matrix4x4d.FromRowMajor(1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1);
            var folder = Copy();
            DatasetFaults.EditPoses(folder, m => m * flip);
            var report = Check(folder);
            AssertCaughtBy(report, "multi-view geometry");
            AssertCaughtBy(report, "depth vs normals");
        }

        [Test]
        public void WrongFieldOfViewIsCaught()
        {
            // The original plugin's bug: the vertical field of view written as camera_angle_x (images 96×72).
            var folder = Copy();
            DatasetFaults.EditTransforms(folder, json =>
            {
                json["camera_angle_x"] = json["camera_angle_y"];
                json.Remove("fl_x");
                json.Remove("fl_y");
            });
            AssertCaughtBy(Check(folder), "multi-view geometry");
        }

        [Test]
        public void NormalsInTheCameraFrameAreCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsNormal, (png, s, file) =>
            {
                var m = DatasetFaults.PoseOf(folder, file);
                for (var i = 0; i < s.Length; i += 3)
                {
                    if ((s[i] | s[i + 1] | s[i + 2]) == 0) continue;
                    var n = new Vector3d(s[i] / 127.5 - 1, s[i + 1] / 127.5 - 1, s[i + 2] / 127.5 - 1);
                    // Rᵀ·n: the world normal in the camera's frame.
                    var c = new Vector3d(Vector3d.Dot(m.Column(0), n), Vector3d.Dot(m.Column(1), n), Vector3d.Dot(m.Column(2), n)).Normalized();
                    s[i] = NormalEncoding.Component((float)c.X);
                    s[i + 1] = NormalEncoding.Component((float)c.Y);
                    s[i + 2] = NormalEncoding.Component((float)c.Z);
                }
            });
            AssertCaughtBy(Check(folder), "depth vs normals");
        }

        [Test]
        public void EmptiedAlphaIsCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsColour, (png, s, _) => { for (var i = 3; i < s.Length; i += 4) s[i] = 0; });
            var report = Check(folder);
            AssertCaughtBy(report, "alpha vs mask");
            Assert.That(report.Problems.Any(p => p.Message.Contains("alpha is 0 everywhere")), Is.True);
        }

        [Test]
        public void VeiledAlphaIsCaught()
        {
            // A full-screen renderer feature drawn over the frame at 90 % opacity (unity-layer-review.md S3-1).
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsColour, (png, s, _) => { for (var i = 3; i < s.Length; i += 4) s[i] = Math.Max(s[i], (byte)230); });
            var report = Check(folder);
            AssertCaughtBy(report, "alpha vs mask");
            Assert.That(report.Problems.Any(p => p.Message.Contains("everywhere")), Is.True);
        }

        [Test]
        public void ColourShiftedByOnePixelIsCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, DatasetFaults.IsColour, (png, s, _) => DatasetFaults.ShiftRight(png, s, 1));
            var report = Check(folder);
            AssertCaughtBy(report, "colour vs geometry");
            Assert.That(report.Problems.First(p => p.Check == "colour vs geometry").Message, Does.Contain("1 px right"));
        }
    }
}
