using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ScenePathTests
    {
        static readonly string Project = Path.Combine(Path.GetTempPath(), "Project");

        static string InProject(params string[] parts) => Path.Combine(Project, Path.Combine(parts));

        [Test]
        public void AnAssetPathIsTakenAsTheWindowSavesIt_WhereverTheConfigIs()
        {
            Assert.That(ScenePath.Resolve("Assets/Scenes/Lego.unity", InProject("Configs", "lego.json"), Project), Is.EqualTo("Assets/Scenes/Lego.unity"));
            Assert.That(ScenePath.Resolve("Packages/com.example.scenes/Lego.unity", "/elsewhere/lego.json", Project), Is.EqualTo("Packages/com.example.scenes/Lego.unity"));
        }

        [Test]
        public void ANameBesideTheConfigFollowsTheConfig_AsInTheDevelopmentProject()
        {
            Assert.That(ScenePath.Resolve("NeRFSample.unity", InProject("Assets", "Samples", "NeRFSample", "nerf-sample.json"), Project),
                Is.EqualTo("Assets/Samples/NeRFSample/NeRFSample.unity"));
        }

        [Test]
        public void ANameBesideTheConfigFollowsTheConfig_WherePackageManagerImportsTheSample()
        {
            // Assets/Samples/<package display name>/<version>/<sample display name>/, names with spaces.
            var config = InProject("Assets", "Samples", "NeRF Dataset Creator", "0.1.0", "NeRF Sample", "nerf-sample.json");
            Assert.That(ScenePath.Resolve("NeRFSample.unity", config, Project),
                Is.EqualTo("Assets/Samples/NeRF Dataset Creator/0.1.0/NeRF Sample/NeRFSample.unity"));
        }

        [Test]
        public void RelativeSegmentsAndBackslashesResolveFromTheConfigsFolder()
        {
            var config = InProject("Assets", "Configs", "lego.json");
            Assert.That(ScenePath.Resolve("../Scenes/Lego.unity", config, Project), Is.EqualTo("Assets/Scenes/Lego.unity"));
            Assert.That(ScenePath.Resolve(@"..\Scenes\Lego.unity", config, Project), Is.EqualTo("Assets/Scenes/Lego.unity"));
            Assert.That(ScenePath.Resolve("./Lego.unity", config, Project), Is.EqualTo("Assets/Configs/Lego.unity"));
        }

        [Test]
        public void AConfigOutsideTheProjectCanStillNameASceneInsideIt()
        {
            Assert.That(ScenePath.Resolve(InProject("Assets", "Scenes", "Lego.unity"), "/build/configs/lego.json", Project), Is.EqualTo("Assets/Scenes/Lego.unity"));
        }

        [Test]
        public void APathLeavingTheProjectIsNull()
        {
            Assert.That(ScenePath.Resolve("../../Lego.unity", InProject("Assets", "lego.json"), Project), Is.Null);
            Assert.That(ScenePath.Resolve("Lego.unity", "/build/configs/lego.json", Project), Is.Null);
        }

        [Test]
        public void NoSceneIsEmpty()
        {
            Assert.That(ScenePath.Resolve("", InProject("lego.json"), Project), Is.EqualTo(""));
            Assert.That(ScenePath.Resolve("  ", InProject("lego.json"), Project), Is.EqualTo(""));
            Assert.That(ScenePath.Resolve(null, InProject("lego.json"), Project), Is.EqualTo(""));
        }
    }
}
