using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The time keys as the dynamic loaders read them, dataset_config.json's record, and validate's time checks.</summary>
    [TestFixture]
    public class TimeDatasetTests
    {
        static DatasetSettings Settings(TimeMode mode, int train, int val, int test, int steps = 0)
        {
            var s = new DatasetSettings { Seed = 5, Width = 16, Height = 16 };
            s.Train.Count = train;
            s.Val.Count = val;
            s.Test.Count = test;
            s.Time.Mode = mode;
            s.Time.StartSeconds = 2;
            s.Time.EndSeconds = 6;
            s.Time.Steps = steps;
            return s;
        }

        static JArray Frames(CapturePlan plan, DatasetSplit split) => (JArray)JObject.Parse(BlenderTransformsWriter.Write(plan, split))["frames"];

        [Test]
        public void DNerfReadsEverySplitFromTimeZero()
        {
            // load_blender.py lines 96–99: cur_time = frame['time']; assert times[0] == 0 for every split.
            var plan = CapturePlan.Build(Settings(TimeMode.Monocular, 9, 4, 5), PlanTarget.AtOrigin);
            foreach (var split in DatasetSplits.All)
            {
                var times = Frames(plan, split).Select(f => (double)f["time"]).ToList();
                Assert.That(times[0], Is.EqualTo(0), DatasetSplits.Name(split));
                Assert.That(times, Is.Ordered, DatasetSplits.Name(split));
                Assert.That(times.All(t => t >= 0 && t <= 1), Is.True);
            }
        }

        [Test]
        public void FourDGaussiansTimelineMapsOurTimesToThemselves()
        {
            // dataset_readers.py read_timeline (lines 298–312): the sorted set of train ∪ test times, each divided by the
            // largest; readCamerasFromTransforms (line 271) looks each frame's time up in that map.
            var plan = CapturePlan.Build(Settings(TimeMode.Monocular, 9, 4, 5), PlanTarget.AtOrigin);
            var timeline = Frames(plan, DatasetSplit.Train).Concat(Frames(plan, DatasetSplit.Test)).Select(f => (double)f["time"]).Distinct().OrderBy(t => t).ToList();
            var max = timeline.Max();
            var mapper = timeline.ToDictionary(t => t, t => t / max);
            foreach (var frame in Frames(plan, DatasetSplit.Test))
                Assert.That(mapper[(double)frame["time"]], Is.EqualTo((double)frame["time"]));
        }

        [Test]
        public void TimeSecondsFollowTheRecordedMapping()
        {
            var plan = CapturePlan.Build(Settings(TimeMode.MultiView, 2, 1, 1, 5), PlanTarget.AtOrigin);
            var config = JObject.Parse(DatasetConfig.Write(plan, new Provenance(new System.DateTime(2026, 1, 1, 0, 0, 0, System.DateTimeKind.Utc))));
            var record = (JObject)config["time"];
            Assert.That((string)record["mode"], Is.EqualTo("multi-view"));
            Assert.That((double)record["startSeconds"], Is.EqualTo(2));
            Assert.That((double)record["endSeconds"], Is.EqualTo(6));
            Assert.That((int)record["steps"], Is.EqualTo(5));
            Assert.That((int)config["views"]["train"], Is.EqualTo(10), "2 cameras × 5 steps");
            Assert.That((string)config["settings"]["time"]["mode"], Is.EqualTo("multi-view"));
            var frames = Frames(plan, DatasetSplit.Train);
            // r_5 is camera 1 at step 2: time 0.5, 2 + 0.5·4 = 4 s.
            Assert.That((string)frames[5]["file_path"], Is.EqualTo("./train/r_5"));
            Assert.That((double)frames[5]["time"], Is.EqualTo(0.5));
            Assert.That((double)frames[5]["time_seconds"], Is.EqualTo(4));
            Assert.That((int)frames[5]["time_step"], Is.EqualTo(2));
            Assert.That((int)frames[5]["camera_id"], Is.EqualTo(1));
            Assert.That(frames.Select(f => (string)((JObject)f).Properties().ElementAt(3).Name).Distinct(), Is.EqualTo(new[] { "time" }),
                "time follows transform_matrix");
        }

        [Test]
        public void StaticTransformsHaveNoTimeKeys()
        {
            var plan = CapturePlan.Build(Settings(TimeMode.Static, 2, 1, 1), PlanTarget.AtOrigin);
            Assert.That(BlenderTransformsWriter.Write(plan, DatasetSplit.Train), Does.Not.Contain("time"));
            Assert.That(DatasetConfig.Write(plan, new Provenance(new System.DateTime(2026, 1, 1, 0, 0, 0, System.DateTimeKind.Utc))), Does.Not.Contain("\"time\""));
        }

        static DatasetValidationReport Written(DatasetSettings s, System.Action<string> tamper = null)
        {
            var temp = new TempFolder();
            try
            {
                var folder = temp.Combine("d");
                TestDatasets.FromPlan(folder, CapturePlan.Build(s, PlanTarget.AtOrigin));
                tamper?.Invoke(folder);
                return DatasetValidator.Validate(folder);
            }
            finally
            {
                temp.Dispose();
            }
        }

        static void EditFrames(string folder, DatasetSplit split, System.Action<JArray> edit)
        {
            var path = Path.Combine(folder, DatasetLayout.TransformsFileName(split));
            var root = JObject.Parse(File.ReadAllText(path));
            edit((JArray)root["frames"]);
            File.WriteAllText(path, root.ToString());
        }

        static IEnumerable<string> Messages(DatasetValidationReport r) => r.Problems.Select(p => p.ToString());

        [Test]
        public void OwnDynamicDatasetsValidate()
        {
            Assert.That(Messages(Written(Settings(TimeMode.Monocular, 6, 3, 3))), Is.Empty);
            Assert.That(Messages(Written(Settings(TimeMode.MultiView, 3, 1, 2, 4))), Is.Empty);
        }

        [Test]
        public void MissingMultiViewFramesAreNamed()
        {
            var report = Written(Settings(TimeMode.MultiView, 3, 1, 2, 4), f => EditFrames(f, DatasetSplit.Train, frames => frames.RemoveAt(7)));
            Assert.That(Messages(report).Single(), Does.Contain("1 (camera, step) pairs of 3 cameras × 4 steps are missing (camera 1 step 2)"));
        }

        [Test]
        public void TimesOutOfRangeOrOrderOrMappingAreProblems()
        {
            var report = Written(Settings(TimeMode.Monocular, 6, 3, 3), f => EditFrames(f, DatasetSplit.Train, frames =>
            {
                frames[2]["time"] = 1.5;
                var t = frames[4]["time"];
                frames[4]["time"] = frames[3]["time"];
                frames[3]["time"] = t;
            }));
            var messages = Messages(report).ToList();
            Assert.That(messages, Has.Some.Contains("frame 2 (./train/r_2): time = 1.5 is outside [0, 1]"));
            Assert.That(messages, Has.Some.Contains("frame 4 (./train/r_4): time = 0.6 is before the previous frame's 0.8"));
            Assert.That(messages, Has.Some.Contains("frame 3 (./train/r_3): time_seconds = 4.4 but time 0.8 maps to 5.2 s"));
        }

        [Test]
        public void ASplitThatDoesNotStartAtZeroBreaksDNerf()
        {
            var report = Written(Settings(TimeMode.Monocular, 6, 3, 3), f => EditFrames(f, DatasetSplit.Val, frames => frames.RemoveAt(0)));
            Assert.That(Messages(report), Has.Some.Contains("transforms_val.json frame 0 (./val/r_1): time = 0.3, but D-NeRF's load_blender.py asserts"));
        }

        [Test]
        public void ForeignDatasetsWithSomeTimesMissingAreProblems()
        {
            // A D-NeRF-style dataset without our dataset_config.json record.
            var report = Written(Settings(TimeMode.Monocular, 4, 2, 2), f =>
            {
                File.Delete(Path.Combine(f, DatasetLayout.ConfigFileName));
                EditFrames(f, DatasetSplit.Test, frames => ((JObject)frames[1]).Remove("time"));
            });
            Assert.That(Messages(report).Single(), Does.Contain("transforms_test.json: 1 of 2 frames have no \"time\""));
        }

        [Test]
        public void ConvertWarnsThatTimeIsDropped()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("d");
                TestDatasets.FromPlan(folder, CapturePlan.Build(Settings(TimeMode.Monocular, 4, 2, 2), PlanTarget.AtOrigin));
                var result = DatasetConverter.Convert(folder, ExportTarget.Nerfstudio);
                Assert.That(result.Warnings.Select(w => w.Field), Has.Member("time"));
            }
        }
    }
}
