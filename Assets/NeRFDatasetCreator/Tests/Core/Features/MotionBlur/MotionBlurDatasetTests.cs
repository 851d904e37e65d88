using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A motion-blurred analytic dataset written through the capture's own Core path (<see cref="AnalyticDataset"/>:
    /// sub-frame renders at the schedule's poses, <see cref="SubFrameAccumulator"/>, <see cref="ViewFileWriter"/>), its
    /// keys read back with instant-ngp's formula, its self-check, and the blur bugs the check must catch.
    /// </summary>
    [TestFixture]
    public class MotionBlurDatasetTests
    {
        TempFolder _temp;
        string _global, _rolling;
        int _copies;

        static AnalyticDataset.Options Options(double readout) => new AnalyticDataset.Options
        {
            Width = 64, Height = 48, Supersampling = 2, Train = 4, Val = 1, Test = 1, PointCloud = 0,
            MotionBlur = new MotionBlurSettings
            {
                Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.25, ShakeDegrees = 2, SubFrames = 12, Readout = readout,
            },
        };

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _global = AnalyticDataset.Write(_temp.Path, "blurred", Options(0));
            _rolling = AnalyticDataset.Write(_temp.Path, "rolling", Options(0.4));
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12)));
            return report;
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ACorrectBlurredCapturePassesEveryCheckIncludingTheBlurCheck(bool rolling)
        {
            var report = Check(rolling ? _rolling : _global);
            Assert.That(report.Failed, Is.False);
            Assert.That(report.Results.Single(r => r.Name == "motion blur").Status, Is.EqualTo(DatasetCheckStatus.Passed));
            Assert.That(report.Results.Single(r => r.Name == "alpha vs mask").Status, Is.EqualTo(DatasetCheckStatus.Passed), "checked on the sharp image");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void WrittenKeysReadBackWithInstantNgpsFormulaGiveTheMidPoseAndTheSubFramePoses(bool rolling)
        {
            var folder = rolling ? _rolling : _global;
            var readout = rolling ? 0.4 : 0;
            var json = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")));
            var rs = json["rolling_shutter"].Select(t => (double)t).ToArray();
            Assert.That(rs, Is.EqualTo(new[] { 0, 0, readout, 1 - readout }));
            Assert.That((int)json["motion_blur"]["sub_frames"], Is.EqualTo(12));
            // Re-plan the same settings: the schedule's poses are what the images were rendered at.
            var plan = CapturePlan.Build(ReadSettings(folder), new PlanTarget(new Vector3d(1, 2, 3), 1.2, 0));
            var frames = (JArray)json["frames"];
            Assert.That(frames.Count, Is.EqualTo(4));
            for (var i = 0; i < frames.Count; i++)
            {
                var frame = frames[i];
                var start = InstantNgpCameraSlerp.FromJson(frame["transform_matrix_start"]);
                var end = InstantNgpCameraSlerp.FromJson(frame["transform_matrix_end"]);
                var mid = Matrix4x4d.FromRows(frame["transform_matrix"].Select(r => r.Select(c => (double)c).ToArray()).ToArray());
                // The centre row (v = ½) halfway through its exposure (r = ½) is at t = ½: transform_matrix.
                var t = InstantNgpCameraSlerp.PixelTime(rs, 0.5, 0.5, 0.5);
                Assert.That(t, Is.EqualTo(0.5).Within(1e-15));
                Assert.That(InstantNgpCameraSlerp.MaxDifference(InstantNgpCameraSlerp.At(start, end, t), mid), Is.LessThan(1e-12), "frame " + i);
                var view = plan.Views.Where(v => v.Split == DatasetSplit.Train).ElementAt(i);
                foreach (var sub in SubFrameSchedule.For(view.Motion, 12))
                {
                    var rendered = plan.Normalisation.CameraToWorld(sub.Pose);
                    Assert.That(rendered.Determinant3x3, Is.EqualTo(1).Within(1e-12));
                    Assert.That(InstantNgpCameraSlerp.MaxDifference(InstantNgpCameraSlerp.At(start, end, sub.Fraction), rendered), Is.LessThan(1e-12), "frame " + i + " sub-frame " + sub.Index);
                }
                // The shake is what the settings ask: 0.25 Unity units (scale 1) and 2° over the shutter.
                Assert.That(Vector3d.Distance(view.Motion.StartMatrix.Translation, view.Motion.EndMatrix.Translation), Is.EqualTo(0.25).Within(1e-12));
                Assert.That(Vector3d.AngleBetween(view.Motion.Start.Rotation.Forward, view.Motion.End.Rotation.Forward), Is.LessThanOrEqualTo(2 * Math.PI / 180 + 1e-12));
                Assert.That((string)frame["sharp_path"], Is.EqualTo("./train/r_" + i + "_sharp_0000.png"));
                Assert.That(File.Exists(Path.Combine(folder, "train", "r_" + i + "_sharp_0000.png")), Is.True);
            }
        }

        static DatasetSettings ReadSettings(string folder) =>
            DatasetSettingsJson.Read(JObject.Parse(File.ReadAllText(Path.Combine(folder, "dataset_config.json")))["settings"].ToString(), "dataset_config.json").Settings;

        [Test]
        public void TheBlurredImageDiffersFromTheSharpOne()
        {
            var blurred = PngReader.Read(Path.Combine(_global, "train", "r_0.png"));
            var sharp = PngReader.Read(Path.Combine(_global, "train", "r_0_sharp_0000.png"));
            var differing = 0;
            for (var i = 3; i < blurred.Samples.Length; i += 4)
                if (Math.Abs(blurred.Samples[i] - sharp.Samples[i]) > 32) differing++;
            Assert.That(differing, Is.GreaterThan(50), "a few pixels of blur along every edge");
        }

        [Test]
        public void ABlurredDatasetValidatesAndIsProvablyThePluginsOwn()
        {
            Assert.That(OwnDataset.WhyNotReplaceable(_global, true), Is.Null, "the sharp images are the plugin's files, so a replace may delete the folder");
            var report = DatasetValidator.Validate(_global);
            Assert.That(report.Problems, Is.Empty, string.Join("\n", report.Problems));
            Assert.That(report.Warnings.Select(w => w.ToString()), Has.None.Contains("no frame names"));
        }

        [Test]
        public void ValidateFindsASharpImageMissingOutsideOrOfTheWrongLayout()
        {
            // Issue 32 item 20: validate checked depth, normal, mask and id keys but not sharp_path.
            var folder = Copy(_global);
            File.Delete(Path.Combine(folder, "train", "r_1_sharp_0000.png"));
            // A sharp image that is an 8-bit grey PNG (a mask) instead of RGBA.
            File.Copy(Path.Combine(folder, "train", "r_2_mask_0000.png"), Path.Combine(folder, "train", "r_2_sharp_0000.png"), true);
            EditFrames(folder, frame =>
            {
                if ((string)frame["file_path"] == "./train/r_3") frame[MotionBlurKeys.SharpPath] = "../outside_sharp.png";
            });
            var problems = DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()).ToList();
            var text = string.Join("\n", problems);
            Assert.That(problems, Has.Some.Contains("sharp_path ./train/r_1_sharp_0000.png is missing."), text);
            Assert.That(problems, Has.Some.Contains("sharp_path ./train/r_2_sharp_0000.png is 8-bit grey, expected 8-bit RGBA"), text);
            Assert.That(problems, Has.Some.Contains("sharp_path ../outside_sharp.png leaves the dataset folder."), text);
            Assert.That(problems.Count, Is.EqualTo(3), text);
        }

        string Copy(string source) => DatasetFaults.Copy(source, _temp.Combine("fault-" + ++_copies));

        static void EditFrames(string folder, Action<JObject> edit)
        {
            foreach (var split in DatasetSplits.Names)
            {
                var path = Path.Combine(folder, DatasetLayout.TransformsFileName(split));
                var json = JObject.Parse(File.ReadAllText(path));
                foreach (JObject frame in (JArray)json["frames"]) edit(frame);
                File.WriteAllText(path, json.ToString());
            }
        }

        static void AssertCaught(DatasetCheckReport report)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(20));
            Assert.That(report.Failed, Is.True, text);
            Assert.That(report.Results.Single(r => r.Name == "motion blur").Status, Is.EqualTo(DatasetCheckStatus.Failed), text);
            Assert.That(report.Problems.Any(p => p.Check == "motion blur" && p.Frame >= 0 && p.File.StartsWith("./", StringComparison.Ordinal)), Is.True, text);
        }

        [Test]
        public void ABlurWrittenWithoutItsKeysIsCaught()
        {
            var folder = Copy(_global);
            EditFrames(folder, f =>
            {
                f.Remove("transform_matrix_start");
                f.Remove("transform_matrix_end");
            });
            AssertCaught(Check(folder));
        }

        [Test]
        public void KeysOfTwiceTheIntervalAreCaught()
        {
            var folder = Copy(_global);
            EditFrames(folder, f =>
            {
                var start = Matrix(f["transform_matrix_start"]);
                var end = Matrix(f["transform_matrix_end"]);
                // The same motion recorded over an interval twice as long: t = −½ and 1½ of the real one.
                f["transform_matrix_start"] = Json(PoseInterpolation.Lerp(start, end, -0.5));
                f["transform_matrix_end"] = Json(PoseInterpolation.Lerp(start, end, 1.5));
            });
            AssertCaught(Check(folder));
        }

        [Test]
        public void StartAndEndSwappedUnderARollingShutterAreCaught()
        {
            // With a rolling shutter the rows see different parts of the interval, so the direction matters.
            var folder = Copy(_rolling);
            EditFrames(folder, f =>
            {
                var start = f["transform_matrix_start"];
                f["transform_matrix_start"] = f["transform_matrix_end"];
                f["transform_matrix_end"] = start;
            });
            AssertCaught(Check(folder));
        }

        [Test]
        public void ConvertCarriesTheShutterToInstantNgpAndWarnsWhereAFormatHoldsOnePosePerImage()
        {
            var folder = Copy(_rolling);
            var ngp = DatasetConverter.Convert(folder, ExportTarget.Ngp);
            Assert.That(ngp.Warnings.Any(w => w.Field.StartsWith("transform_matrix_start", StringComparison.Ordinal)), Is.False);
            var written = JObject.Parse(File.ReadAllText(ngp.MainFile));
            var source = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")));
            Assert.That(written["rolling_shutter"].Select(t => (double)t), Is.EqualTo(new[] { 0, 0, 0.4, 0.6 }));
            for (var i = 0; i < 4; i++)
                foreach (var key in new[] { "transform_matrix_start", "transform_matrix_end" })
                    Assert.That(Matrix(written["frames"][i][key]), Is.EqualTo(Matrix(source["frames"][i][key])), key + " of frame " + i);
            foreach (var target in new[] { ExportTarget.Nerfstudio, ExportTarget.Colmap })
            {
                var result = DatasetConverter.Convert(folder, target);
                Assert.That(result.Warnings.Any(w => w.Field == "transform_matrix_start/_end" && w.Reason.Contains("as if they were sharp")), Is.True, ExportTargets.Name(target));
            }
        }

        static Matrix4x4d Matrix(JToken t) => Matrix4x4d.FromRows(t.Select(r => r.Select(c => (double)c).ToArray()).ToArray());

        static JArray Json(Matrix4x4d m) => new JArray(m.ToRows().Select(r => new JArray(r.Cast<object>().ToArray())));
    }
}
