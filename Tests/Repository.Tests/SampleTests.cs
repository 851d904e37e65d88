using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// The sample's batch configs (README's first command captures nerf-sample.json; dynamic-capture.md's worked
    /// example the dynamic ones): each must read, validate, plan and point at real things.
    /// </summary>
    [TestFixture]
    public class SampleTests
    {
        static string SampleFolder => RepositoryPaths.Combine("Assets", "Samples", "NeRFSample");
        static string ConfigPath => Path.Combine(SampleFolder, "nerf-sample.json");

        /// <summary>Every config of the sample folder, by file name.</summary>
        static IEnumerable<string> Configs() =>
            Directory.GetFiles(SampleFolder, "*.json").Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal);

        [Test]
        public void TheSampleShipsTheStaticAndTheDynamicConfigs()
        {
            Assert.That(Configs(), Is.EquivalentTo(new[] { "nerf-sample.json", "nerf-sample-dynamic.json", "nerf-sample-multiview.json" }));
        }

        [TestCaseSource(nameof(Configs))]
        public void EverySampleConfigReadsWithoutWarningsAndValidates(string file)
        {
            var read = DatasetSettingsJson.ReadFile(Path.Combine(SampleFolder, file));
            Assert.That(read.Warnings.Select(w => w.ToString()), Is.Empty);
            Assert.That(SettingsValidator.Validate(read.Settings).Select(p => p.ToString()), Is.Empty);
        }

        [TestCaseSource(nameof(Configs))]
        public void EverySampleConfigPlansWithoutProblemsOrWarnings(string file)
        {
            var settings = DatasetSettingsJson.ReadFile(Path.Combine(SampleFolder, file)).Settings;
            var plan = CapturePlan.Build(settings, settings.Time.Enabled ? AnimatedTargetAsUnityMeasuresIt() : new PlanTarget(new Vector3d(0, 0, 0), 1));
            Assert.That(plan.Warnings.Select(w => w.ToString()), Is.Empty);
            if (!settings.Time.Enabled) return;
            Assert.That(plan.Time, Is.Not.Null);
            Assert.That(plan.Time.EndSeconds, Is.EqualTo(2.0), "end \"clip\" is the clip's length");
        }

        /// <summary>
        /// What TimeMeasurement gives planning for NeRFAnimatedTarget: the clip's length, and the bounds of the cube
        /// (the built-in unit cube scaled 0.3 × 0.3 × 0.8) over its motion, sampled densely from the clip's curves,
        /// about the root at (3, 0, 0). By hand: x from −0.75 (at 0 s, −0.6 − 0.15) to 1.0 (at 2 s, turned 90°: 0.6 + 0.4),
        /// y from 0.25 to 0.95 (0.8 ± 0.15 at 1 s), z within ±√(0.15² + 0.4²) (the box's xz diagonal, reached at a
        /// 20.6° turn): radius √(0.875² + 0.35² + 0.15² + 0.4²) ≈ 1.035, under the 1.3 the loaders' boxes allow at distance 4.
        /// </summary>
        internal static PlanTarget AnimatedTargetAsUnityMeasuresIt()
        {
            var clip = SampleClip.Load();
            double[] min = { double.MaxValue, double.MaxValue, double.MaxValue }, max = { double.MinValue, double.MinValue, double.MinValue };
            for (var i = 0; i <= 200; i++)
            {
                var (position, euler) = clip.Pose(clip.StopTime * i / 200);
                var yaw = euler[1] * Math.PI / 180;
                foreach (var cx in new[] { -0.15, 0.15 })
                foreach (var cy in new[] { -0.15, 0.15 })
                foreach (var cz in new[] { -0.4, 0.4 })
                {
                    // A turn about +y (Unity, left-handed): x' = x cos + z sin, z' = −x sin + z cos.
                    var corner = new[] { 3 + position[0] + cx * Math.Cos(yaw) + cz * Math.Sin(yaw), position[1] + cy, position[2] - cx * Math.Sin(yaw) + cz * Math.Cos(yaw) };
                    for (var a = 0; a < 3; a++)
                    {
                        min[a] = Math.Min(min[a], corner[a]);
                        max[a] = Math.Max(max[a], corner[a]);
                    }
                }
            }
            var half = Enumerable.Range(0, 3).Select(a => (max[a] - min[a]) / 2).ToArray();
            var radius = Math.Sqrt(half.Sum(h => h * h));
            Assert.That(radius, Is.EqualTo(Math.Sqrt(0.875 * 0.875 + 0.35 * 0.35 + 0.15 * 0.15 + 0.4 * 0.4)).Within(1e-4));
            return new PlanTarget(new Vector3d((min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2), radius, clip.StopTime);
        }

        [Test]
        public void TheReadmeCommandNamesTheSampleConfig()
        {
            var readme = File.ReadAllText(RepositoryPaths.Combine("README.md"));
            Assert.That(readme, Does.Contain("-executeMethod NerfDatasetCreator.Editor.BatchCapture.Run -nerfConfig Assets/Samples/NeRFSample/nerf-sample.json"));
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

        [TestCaseSource(nameof(Configs))]
        public void EverySampleConfigsSceneExistsAndHoldsItsTarget(string file)
        {
            AssertSceneHoldsTarget(RepositoryPaths.Root, Path.Combine(SampleFolder, file), "Assets/Samples/NeRFSample/NeRFSample.unity");
        }

        /// <summary>
        /// Package Manager ▸ Samples ▸ Import copies Samples~/NeRFSample to
        /// Assets/Samples/&lt;package displayName&gt;/&lt;version&gt;/&lt;sample displayName&gt;/ (UnityCsReference,
        /// PackageSample.cs, Sample.importPath). The batch entry resolves each config's scene from there (ScenePath).
        /// </summary>
        [TestCaseSource(nameof(Configs))]
        public void EverySampleConfigFindsItsSceneWherePackageManagerImportsTheSample(string file)
        {
            var manifest = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(RepositoryPaths.Combine("package.json")));
            var project = Path.Combine(Path.GetTempPath(), "nerf-imported-sample-" + Guid.NewGuid().ToString("N"));
            try
            {
                var relative = "Assets/Samples/" + (string)manifest["displayName"] + "/" + (string)manifest["version"] + "/" + (string)manifest["samples"][0]["displayName"];
                Assert.That(relative, Is.EqualTo("Assets/Samples/NeRF Dataset Creator/0.2.0/NeRF Sample"));
                var imported = Path.Combine(project, relative);
                Directory.CreateDirectory(imported);
                foreach (var source in Directory.GetFiles(SampleFolder))
                    File.Copy(source, Path.Combine(imported, Path.GetFileName(source)));
                AssertSceneHoldsTarget(project, Path.Combine(imported, file), relative + "/NeRFSample.unity");
            }
            finally
            {
                if (Directory.Exists(project)) Directory.Delete(project, true);
            }
        }

        static void AssertSceneHoldsTarget(string projectRoot, string configPath, string expectedScene)
        {
            var settings = DatasetSettingsJson.ReadFile(configPath).Settings;
            var resolved = ScenePath.Resolve(settings.Scene, configPath, projectRoot);
            Assert.That(resolved, Is.EqualTo(expectedScene));
            var scene = Path.Combine(projectRoot, Path.Combine(resolved.Split('/')));
            Assert.That(File.Exists(scene), Is.True, resolved);
            Assert.That(Regex.IsMatch(File.ReadAllText(scene), @"^\s*m_Name: " + Regex.Escape(settings.Target) + @"\s*$", RegexOptions.Multiline),
                Is.True, "the scene has a GameObject named " + settings.Target);
        }
    }
}
