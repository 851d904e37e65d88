using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>convert --to ngp</c> takes instant-ngp's cube from the dataset: the <c>aabb_scale</c> of its
    /// transforms_train.json and the target recorded in dataset_config.json. Reaches below are worked by hand from
    /// x_out = s·((x, z, y)_Unity − centre) and reach = |x_out(target centre)| + s·b.
    /// </summary>
    public class NgpAabbFromDatasetTests
    {
        LegoDataset _lego;

        [SetUp]
        public void SetUp() => _lego = new LegoDataset();

        [TearDown]
        public void TearDown() => _lego.Dispose();

        void DeclareAabbScale(int value)
        {
            var path = Path.Combine(_lego.Root, "transforms_train.json");
            var json = JObject.Parse(File.ReadAllText(path));
            json["aabb_scale"] = value;
            File.WriteAllText(path, json.ToString());
        }

        void WriteConfig(double[] unityCentre, double boundingRadius, double scale, double[] centre)
        {
            var config = new JObject
            {
                ["generator"] = PluginInfo.Name,
                ["target"] = new JObject { ["unityCentre"] = new JArray(unityCentre), ["boundingRadius"] = boundingRadius },
                ["scene_normalisation"] = new JObject { ["scale"] = scale, ["centre"] = new JArray(centre) },
            };
            File.WriteAllText(Path.Combine(_lego.Root, DatasetLayout.ConfigFileName), config.ToString());
        }

        int ExportedAabbScale(out IReadOnlyList<ValidationProblem> warnings)
        {
            var result = DatasetConverter.Convert(_lego.Root, ExportTarget.Ngp);
            warnings = result.Warnings;
            return (int)JObject.Parse(File.ReadAllText(result.MainFile))["aabb_scale"];
        }

        [Test]
        public void TheDeclaredAabbScaleIsKept()
        {
            DeclareAabbScale(4);
            Assert.That(ExportedAabbScale(out var warnings), Is.EqualTo(4));
            Assert.That(warnings.Select(w => w.Field), Does.Not.Contain("aabb_scale"));
        }

        [Test]
        public void TheRecordedTargetSetsTheCube_WhenNothingIsDeclared()
        {
            // Unity (1, 3, 2) → Blender (1, 2, 3) = the centre → origin; reach = s·b = 2·1.25 = 2.5 → 2·0.33·2.5 = 1.65 → 2.
            WriteConfig(new[] { 1.0, 3, 2 }, 1.25, 2, new[] { 1.0, 2, 3 });
            Assert.That(DatasetTargetReach.Read(_lego.Root), Is.EqualTo(2.5).Within(1e-12));
            Assert.That(ExportedAabbScale(out _), Is.EqualTo(2));
        }

        [Test]
        public void AnOffCentreTargetCountsItsDistanceFromTheOrigin()
        {
            // Unity (4, 3, 2) → Blender (4, 2, 3); minus the centre (1, 2, 3) = (3, 0, 0); ×2 = (6, 0, 0).
            // reach = 6 + 2·0.75 = 7.5 → 2·0.33·7.5 = 4.95 → 8.
            WriteConfig(new[] { 4.0, 3, 2 }, 0.75, 2, new[] { 1.0, 2, 3 });
            Assert.That(DatasetTargetReach.Read(_lego.Root), Is.EqualTo(7.5).Within(1e-12));
            Assert.That(ExportedAabbScale(out _), Is.EqualTo(8));
        }

        [Test]
        public void ADeclaredCubeTooSmallForTheTarget_IsRaisedWithAWarning()
        {
            DeclareAabbScale(1);
            WriteConfig(new[] { 1.0, 3, 2 }, 1.25, 2, new[] { 1.0, 2, 3 }); // reach 2.5 needs 2

            Assert.That(ExportedAabbScale(out var warnings), Is.EqualTo(2));
            Assert.That(warnings.Single(w => w.Field == "aabb_scale").Reason, Does.Contain("2.5"));
        }

        [Test]
        public void ATargetBeyondTheLargestCube_IsAWarning()
        {
            WriteConfig(new[] { 0.0, 0, 0 }, 200, 1, new[] { 0.0, 0, 0 }); // 2·0.33·200 = 132 > 128
            Assert.That(ExportedAabbScale(out var warnings), Is.EqualTo(128));
            Assert.That(warnings.Single(w => w.Field == "aabb_scale").Reason, Does.Contain("cut off"));
        }

        [Test]
        public void UnknownBounds_LeaveTheDeclaredValue()
        {
            DeclareAabbScale(2);
            File.WriteAllText(Path.Combine(_lego.Root, DatasetLayout.ConfigFileName),
                new JObject { ["target"] = new JObject { ["unityCentre"] = new JArray(0.0, 0, 0), ["boundingRadius"] = null } }.ToString());
            Assert.That(DatasetTargetReach.Read(_lego.Root), Is.Null);
            Assert.That(ExportedAabbScale(out _), Is.EqualTo(2));
        }

        [Test]
        public void AMalformedTargetRecord_IsAWarningNotAFailure()
        {
            File.WriteAllText(Path.Combine(_lego.Root, DatasetLayout.ConfigFileName),
                new JObject { ["target"] = new JObject { ["unityCentre"] = "here", ["boundingRadius"] = 1 } }.ToString());
            Assert.That(ExportedAabbScale(out var warnings), Is.EqualTo(1));
            Assert.That(warnings.Select(w => w.Field), Does.Contain(DatasetLayout.ConfigFileName + ": target"));
        }
    }
}
