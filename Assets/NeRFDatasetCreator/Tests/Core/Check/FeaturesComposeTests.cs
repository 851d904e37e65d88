using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The optional outputs built side by side (labels, lens, exposure, motion blur) together in one capture, through
    /// the capture's own writers and the lens's wide render: each feature's files are written and every check that has
    /// something to judge passes. Catches what the per-feature tests cannot: a stage that drops another's channel (the
    /// lens resampling losing the id pass) or treats the images differently (the sharp image of a blurred view left
    /// unexposed while the blurred one is exposed).
    /// </summary>
    [TestFixture]
    public class FeaturesComposeTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12)));
            return report;
        }

        static void AssertPassed(DatasetCheckReport report, params string[] checks)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(20));
            Assert.That(report.Problems, Is.Empty, text);
            foreach (var name in checks)
                Assert.That(report.Results.Single(r => r.Name == name).Status, Is.EqualTo(DatasetCheckStatus.Passed), name + "\n" + text);
        }

        [Test]
        public void LabelsThroughALensWithExposureWriteEveryFileAndPassEveryCheck()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "lens-labels", new AnalyticDataset.Options
            {
                Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 },
                ThroughWideRender = true, DataAtOutputSize = false, VerticalFovDegrees = 70, Distance = 1.8, Width = 128, Height = 96,
                Labels = true,
                Configure = s => s.Exposure.Mode = ExposureMode.Random,
            });

            Assert.That(File.Exists(Path.Combine(folder, "train", "r_0_instance_0000.png")), Is.True);
            Assert.That(File.Exists(Path.Combine(folder, "train", "r_0_clean.png")), Is.True);
            // The id pass survives the lens stage: the maps hold the layout's objects, not only background.
            var ids = PngGray16Reader.Read(Path.Combine(folder, "train", "r_0_instance_0000.png"), out _, out _);
            Assert.That(ids.Distinct().Count(i => i != 0), Is.GreaterThanOrEqualTo(2));
            AssertPassed(Check(folder), "multi-view geometry", InstanceMaskCheck.CheckName, InstanceReprojectionCheck.CheckName, "exposure");
        }

        [Test]
        public void MotionBlurWithLabelsAndExposureWritesEveryFileAndPassesEveryCheck()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "blur-labels", new AnalyticDataset.Options
            {
                Width = 64, Height = 48, Supersampling = 2, Train = 4, Val = 1, Test = 1, PointCloud = 0,
                MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.25, ShakeDegrees = 2, SubFrames = 12 },
                Labels = true,
                Configure = s => s.Exposure.Mode = ExposureMode.Random,
            });

            foreach (var suffix in new[] { "_sharp_0000.png", "_clean.png", "_instance_0000.png" })
                Assert.That(File.Exists(Path.Combine(folder, "train", "r_0" + suffix)), Is.True, suffix);
            AssertPassed(Check(folder), "motion blur", "alpha vs mask", InstanceMaskCheck.CheckName, "exposure");
        }

        [Test]
        public void MotionBlurThroughALensPassesEveryCheck()
        {
            // A global shutter: the sub-frames are averaged in the wide frame, then resampled (a rolling one is refused).
            var folder = AnalyticDataset.Write(_temp.Path, "blur-lens", new AnalyticDataset.Options
            {
                Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 },
                ThroughWideRender = true, DataAtOutputSize = false, VerticalFovDegrees = 70, Distance = 1.8, Width = 128, Height = 96,
                PointCloud = 0,
                MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.1, ShakeDegrees = 1, SubFrames = 12 },
            });
            Assert.That(File.Exists(Path.Combine(folder, "train", "r_0_sharp_0000.png")), Is.True);
            AssertPassed(Check(folder), "motion blur", "multi-view geometry");
        }
    }
}
