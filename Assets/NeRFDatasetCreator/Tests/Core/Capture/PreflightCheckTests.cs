using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The preflight's choices (issue 21): when it runs, which views (the plan's own, spread over the splits), at what
    /// size, and its setting in config files; and that a dataset holding its check report is still provably ours.
    /// </summary>
    public class PreflightCheckTests
    {
        static readonly PlanTarget Target = new PlanTarget(new Vector3d(1, 2, 3), 0.5);
        TempFolder _temp;

        [SetUp]
        public void CreateProject() => _temp = new TempFolder();

        [TearDown]
        public void DeleteProject() => _temp.Dispose();

        static DatasetSettings Settings(int train, int val, int test)
        {
            var s = new DatasetSettings { Name = "big", Width = 800, Height = 600, Supersampling = 2, PointCloudPoints = 100000 };
            s.Train.Count = train;
            s.Val.Count = val;
            s.Test.Count = test;
            s.Test.Depth = ExtraOutput.Png;
            return s;
        }

        [Test]
        public void OnlyCapturesOfMoreThanAFewDozenViewsAndOnlyWhenOn()
        {
            var s = Settings(40, 4, 4);
            Assert.That(PreflightCheck.Needed(s, 48), Is.False);
            Assert.That(PreflightCheck.Needed(s, 49), Is.True);
            s.Preflight = false;
            Assert.That(PreflightCheck.Needed(s, 10000), Is.False);
        }

        [Test]
        public void TheCalibrationIsTheSamePlanSmallerAndNeverPreflightsItself()
        {
            var s = Settings(300, 10, 20);
            var calibration = PreflightCheck.CalibrationSettings(s, "/tmp/x", "calibration");
            Assert.That((calibration.Width, calibration.Height), Is.EqualTo((160, 120)), "800×600 scaled to a 160-pixel long side");
            Assert.That(calibration.Camera.VerticalFovDegrees, Is.EqualTo(s.Camera.VerticalFovDegrees));
            Assert.That(calibration.Supersampling, Is.EqualTo(2));
            Assert.That(calibration.PointCloudPoints, Is.EqualTo(PreflightCheck.MaxPoints));
            Assert.That((calibration.OutputFolder, calibration.Name, calibration.Preflight, calibration.Overwrite), Is.EqualTo(("/tmp/x", "calibration", false, OverwritePolicy.Never)));
            Assert.That((s.Width, s.Preflight, s.PointCloudPoints), Is.EqualTo((800, true, 100000)), "the user's settings are untouched");
            var wide = Settings(300, 10, 20);
            wide.Width = 1920;
            wide.Height = 1080;
            var w = PreflightCheck.CalibrationSettings(wide, "/tmp/x", "c");
            Assert.That((w.Width, w.Height), Is.EqualTo((160, 90)));
            var small = Settings(300, 10, 20);
            small.Width = 100;
            small.Height = 50;
            Assert.That(PreflightCheck.CalibrationSettings(small, "/tmp/x", "c").Width, Is.EqualTo(100), "never scaled up");
        }

        [Test]
        public void TheCalibrationRendersAHandfulOfThePlansOwnViewsFromEverySplit()
        {
            var s = Settings(300, 10, 20);
            var full = DatasetRun.Prepare(s, Target, _temp.Path);
            Assert.That(full.Problems, Is.Empty);
            int views = full.Plan.Views.Count;
            Assert.That(views, Is.EqualTo(330));
            var shard = PreflightCheck.Shard(300, 10, 20);
            Assert.That(shard.Count, Is.EqualTo(10), "every 10th view: val's 10 views keep one");
            Assert.That(PreflightCheck.Shard(10000, 100, 100).Count, Is.EqualTo(10200 / PreflightCheck.Views), "the smallest split would cost 102 views");
            Assert.That(PreflightCheck.Shard(60, 0, 0).Count, Is.EqualTo(5));
            var calibration = DatasetRun.Prepare(PreflightCheck.CalibrationSettings(s, _temp.Path, "calibration"), Target, _temp.Path, shard,
                Path.Combine(_temp.Path, "calibration"));
            Assert.That(calibration.Problems, Is.Empty);
            var picked = calibration.Plan.Views;
            Assert.That(picked.Count, Is.EqualTo(33));
            Assert.That(picked.Select(v => v.Split).Distinct().Count(), Is.EqualTo(3), "train, val and test are all in it");
            foreach (var view in picked)
            {
                var same = full.Plan.Views.Single(v => v.Split == view.Split && v.Index == view.Index);
                Assert.That(view.Pose.Position.X, Is.EqualTo(same.Pose.Position.X).Within(1e-9), "the plan's own pose: " + view.Split + " " + view.Index);
                Assert.That(view.Pose.Rotation.W, Is.EqualTo(same.Pose.Rotation.W).Within(1e-9));
            }
        }

        [Test]
        public void TheSettingIsWrittenOnlyWhenOffAndReadBack()
        {
            var s = new DatasetSettings();
            Assert.That(DatasetSettingsJson.Write(s), Does.Not.Contain("preflight"), "existing configs keep their keys");
            s.Preflight = false;
            var text = DatasetSettingsJson.Write(s);
            Assert.That(text, Does.Contain("\"preflight\": false"));
            Assert.That(DatasetSettingsJson.Read(text).Settings.Preflight, Is.False);
            Assert.That(DatasetSettingsJson.Read("{}").Settings.Preflight, Is.True);
            var error = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{\"preflight\": \"no\"}"));
            Assert.That(error.Message, Does.Contain("preflight").And.Contain("must be true or false"));
        }

        [Test]
        public void ADatasetWithItsCheckReportIsStillProvablyOurs()
        {
            var s = new DatasetSettings { Name = "unit", Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K };
            s.Train.Count = 1;
            s.Val.Count = 1;
            s.Test.Count = 1;
            var run = DatasetRun.Prepare(s, Target, _temp.Path);
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.MattedColour(), SyntheticViews.Data());
            run.Finish(session, new Provenance(new System.DateTime(2026, 11, 27, 10, 0, 0, System.DateTimeKind.Utc), "6000.0.0f1", "unit-test"));
            File.WriteAllText(Path.Combine(run.DatasetFolder, DatasetCheck.ReportFileName), "{}\n");
            Assert.That(OwnDataset.WhyNotOurs(run.DatasetFolder), Is.Null);
            File.WriteAllText(Path.Combine(run.DatasetFolder, "notes.txt"), "mine");
            Assert.That(OwnDataset.WhyNotOurs(run.DatasetFolder), Does.Contain("notes.txt"));
        }
    }
}
