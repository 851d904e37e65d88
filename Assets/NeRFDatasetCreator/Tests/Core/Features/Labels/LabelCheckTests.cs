using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Instance and semantic maps rendered analytically through the capture's writer pass "instance vs mask" and
    /// "instance reprojection"; the id-pass bugs of issue 26, planted in copies, are caught.
    /// </summary>
    [TestFixture]
    public class LabelCheckTests
    {
        TempFolder _temp;
        string _clean;
        int _copies;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _clean = AnalyticDataset.Write(_temp.Path, "labelled", new AnalyticDataset.Options { Labels = true });
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        string Copy() => DatasetFaults.Copy(_clean, _temp.Combine("fault-" + ++_copies));

        static bool IsInstance(string file) => file.EndsWith("_instance_0000.png", StringComparison.Ordinal);

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12)));
            return report;
        }

        static void AssertCaughtBy(DatasetCheckReport report, string check)
        {
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(20));
            Assert.That(report.Results.Single(r => r.Name == check).Status, Is.EqualTo(DatasetCheckStatus.Failed), check + "\n" + text);
            Assert.That(report.Problems.Any(p => p.Check == check && p.Frame >= 0 && p.File.EndsWith("_instance_0000.png", StringComparison.Ordinal)), Is.True, text);
        }

        [Test]
        public void TheLabelledDatasetPassesEveryCheck()
        {
            var report = Check(_clean);
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
            Assert.That(report.Problems, Is.Empty, text);
            foreach (var name in new[] { "alpha vs mask", "depth vs mask", "multi-view geometry", InstanceMaskCheck.CheckName, InstanceReprojectionCheck.CheckName })
                Assert.That(report.Results.Single(r => r.Name == name).Status, Is.EqualTo(DatasetCheckStatus.Passed), name + "\n" + text);
            Assert.That(DatasetValidator.Validate(_clean).Problems, Is.Empty);
        }

        [Test]
        public void TheMapsHoldTheTracedObjectIdsAndTheSemanticMapTheirClasses()
        {
            var table = LabelsJson.ReadFile(Path.Combine(_clean, "labels.json"));
            Assert.That(table.Instances.Select(i => i.Name + ":" + i.ClassName), Is.EqualTo(new[] { "Ball:Sphere", "Glass:Sphere", "Slab:Ground" }));
            var instance = PngGray16Reader.Read(Path.Combine(_clean, "train", "r_0_instance_0000.png"), out var w, out var h);
            var semantic = PngGray16Reader.Read(Path.Combine(_clean, "train", "r_0_semantic_0000.png"), out _, out _);
            var mask = PngReader.Read(Path.Combine(_clean, "train", "r_0_mask_0000.png")).Samples;
            Assert.That((w, h), Is.EqualTo((96, 72)));
            // Every object is seen, and nothing but the three ids and background appears.
            Assert.That(instance.Distinct().OrderBy(i => i), Is.EqualTo(new ushort[] { 0, 1, 2, 3 }));
            for (var i = 0; i < instance.Length; i++)
            {
                Assert.That(instance[i] != 0, Is.EqualTo(mask[i] >= 128), "pixel " + i);
                Assert.That(semantic[i], Is.EqualTo(instance[i] == 0 ? 0 : instance[i] == 3 ? 2 : 1), "pixel " + i);
            }
        }

        [Test]
        public void IdsShiftedByAPixelAreCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, IsInstance, (png, s, _) => DatasetFaults.ShiftRight(png, s, 1));
            AssertCaughtBy(Check(folder), InstanceMaskCheck.CheckName);
        }

        [Test]
        public void TwoObjectsIdsSwappedInOneViewAreCaught()
        {
            var folder = Copy();
            DatasetFaults.EditImages(folder, f => f.EndsWith(Path.Combine("train", "r_2_instance_0000.png"), StringComparison.Ordinal), (png, s, _) =>
            {
                for (var i = 0; i < s.Length; i += 2)
                {
                    var id = (s[i] << 8) | s[i + 1];
                    if (id == 1) s[i + 1] = 3;
                    else if (id == 3) s[i + 1] = 1;
                }
            });
            var report = Check(folder);
            AssertCaughtBy(report, InstanceReprojectionCheck.CheckName);
            Assert.That(report.Problems.Where(p => p.Check == InstanceReprojectionCheck.CheckName).Select(p => p.File).Concat(
                report.Problems.Where(p => p.Check == InstanceReprojectionCheck.CheckName).Select(p => p.Message)).Any(t => t.Contains("r_2")), Is.True);
        }

        [Test]
        public void IdsBlendedAtEdgesAreCaught()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "blended", new AnalyticDataset.Options { Labels = true, BlendIds = true });
            AssertCaughtBy(Check(folder), InstanceMaskCheck.CheckName);
        }

        [Test]
        public void ADynamicCaptureKeepsEveryObjectsIdAcrossTimeSteps()
        {
            var folder = AnalyticDataset.Write(_temp.Path, "moving", new AnalyticDataset.Options { Labels = true, TimeSteps = 3, Train = 6, Val = 2, Test = 2, PointCloud = 0 });
            var report = Check(folder);
            var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
            Assert.That(report.Problems, Is.Empty, text);
            foreach (var name in new[] { InstanceMaskCheck.CheckName, InstanceReprojectionCheck.CheckName })
                Assert.That(report.Results.Single(r => r.Name == name).Status, Is.EqualTo(DatasetCheckStatus.Passed), name + "\n" + text);
        }

        [Test]
        public void AMissingLabelsFileIsCaught()
        {
            var folder = Copy();
            File.Delete(Path.Combine(folder, "labels.json"));
            var report = Check(folder);
            Assert.That(report.Results.Single(r => r.Name == InstanceMaskCheck.CheckName).Status, Is.EqualTo(DatasetCheckStatus.Failed));
            Assert.That(report.Problems.Any(p => p.File == "labels.json" && p.Message.Contains("missing")), Is.True);
            Assert.That(DatasetValidator.Validate(folder).Problems.Any(p => p.ToString().Contains("labels.json")), Is.True);
        }
    }
}
