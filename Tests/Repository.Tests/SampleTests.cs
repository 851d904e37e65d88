using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>The sample that README's first command captures: its config must read, validate and point at real things.</summary>
    [TestFixture]
    public class SampleTests
    {
        static string ConfigPath => RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", "nerf-sample.json");

        [Test]
        public void TheReadmeCommandNamesTheSampleConfig()
        {
            var readme = File.ReadAllText(RepositoryPaths.Combine("README.md"));
            Assert.That(readme, Does.Contain("-executeMethod NerfDatasetCreator.Editor.BatchCapture.Run -nerfConfig Assets/Samples/NeRFSample/nerf-sample.json"));
        }

        [Test]
        public void TheSampleConfigReadsWithoutWarningsAndValidates()
        {
            var read = DatasetSettingsJson.ReadFile(ConfigPath);
            Assert.That(read.Warnings.Select(w => w.ToString()), Is.Empty);
            Assert.That(SettingsValidator.Validate(read.Settings).Select(p => p.ToString()), Is.Empty);
        }

        [Test]
        public void TheSampleConfigPlansWithoutWarnings_SoEveryExportGetsDepthInEverySplit()
        {
            // nerfstudio needs depth_file_path / mask_path on all frames or none: the sample must not make its export drop them.
            var settings = DatasetSettingsJson.ReadFile(ConfigPath).Settings;
            var plan = CapturePlan.Build(settings, new PlanTarget(new Vector3d(0, 0, 0), 1));
            Assert.That(plan.Warnings.Select(w => w.ToString()), Is.Empty);
            Assert.That(DatasetSplits.All.Select(s => ExtraOutputs.HasPng(settings.Split(s).Depth)), Is.All.True);
        }

        [Test]
        public void TheSampleConfigsSceneExistsAndHoldsItsTarget()
        {
            var settings = DatasetSettingsJson.ReadFile(ConfigPath).Settings;
            var scene = RepositoryPaths.Combine(settings.Scene.Split('/'));
            Assert.That(File.Exists(scene), Is.True, settings.Scene);
            Assert.That(Regex.IsMatch(File.ReadAllText(scene), @"^\s*m_Name: " + Regex.Escape(settings.Target) + @"\s*$", RegexOptions.Multiline),
                Is.True, "the scene has a GameObject named " + settings.Target);
        }
    }
}
