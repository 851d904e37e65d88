using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>The package manifest, the development project's manifest and the assembly definitions.</summary>
    [TestFixture]
    public class ManifestTests
    {
        static JObject Json(params string[] path) => JObject.Parse(File.ReadAllText(RepositoryPaths.Combine(path)));

        static JObject Asmdef(string folder, string name) =>
            JObject.Parse(File.ReadAllText(Path.Combine(RepositoryPaths.PluginFolder, folder, name + ".asmdef")));

        [Test]
        public void PackageJsonIsAValidUpmManifest()
        {
            var manifest = Json("package.json");
            // UPM: lowercase reverse-domain name, at most 214 characters, no com.unity. prefix for third parties.
            Assert.That((string)manifest["name"], Does.Match(@"^[a-z0-9-]+(\.[a-z0-9-_]+){2,}$"));
            Assert.That((string)manifest["name"], Does.Not.StartWith("com.unity."));
            Assert.That((string)manifest["version"], Does.Match(@"^\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?$"));
            Assert.That((string)manifest["unity"], Is.EqualTo("2022.3"));
            Assert.That((string)manifest["displayName"], Is.Not.Empty);
            Assert.That((string)manifest["description"], Is.Not.Empty);
            Assert.That((string)manifest["license"], Is.EqualTo("MIT"));
            Assert.That((string)manifest["author"]?["name"], Is.Not.Empty);
            Assert.That((string)manifest["dependencies"]?["com.unity.nuget.newtonsoft-json"], Is.Not.Null);
        }

        [Test]
        public void DevelopmentProjectDependsOnNewtonsoftAndTheTestFramework()
        {
            var dependencies = (JObject)Json("Packages", "manifest.json")["dependencies"];
            Assert.That(dependencies.Properties().Select(p => p.Name),
                Is.SupersetOf(new[] { "com.unity.nuget.newtonsoft-json", "com.unity.test-framework", "com.unity.modules.imageconversion" }));
            Assert.That((string)dependencies["com.unity.nuget.newtonsoft-json"],
                Is.EqualTo((string)Json("package.json")["dependencies"]["com.unity.nuget.newtonsoft-json"]),
                "the project must test the Newtonsoft version the package declares");
        }

        [Test]
        public void PluginVersionInCoreMatchesPackageJson()
        {
            // dataset_config.json records PluginInfo.Version; it must be the version users install.
            var source = File.ReadAllText(Path.Combine(RepositoryPaths.PluginFolder, "Core", "Dataset", "PluginInfo.cs"));
            var match = Regex.Match(source, "Version = \"([^\"]+)\"");
            Assert.That(match.Success, Is.True, "PluginInfo.Version not found");
            Assert.That(match.Groups[1].Value, Is.EqualTo((string)Json("package.json")["version"]));
        }

        [Test]
        public void TheToolPackageCarriesTheCommandNameAndThePackagesVersion()
        {
            // README: dotnet tool install … NerfDatasetCreator.Tool installs the command nerf-dataset.
            var project = System.Xml.Linq.XDocument.Load(Path.Combine(RepositoryPaths.PluginFolder, "Tools~", "nerf-dataset", "nerf-dataset.csproj"));
            string Property(string name) => project.Descendants(name).Single().Value;
            Assert.That(Property("PackAsTool"), Is.EqualTo("true"));
            Assert.That(Property("ToolCommandName"), Is.EqualTo("nerf-dataset"));
            Assert.That(Property("PackageId"), Is.EqualTo("NerfDatasetCreator.Tool"));
            // The version is read from package.json, the one place it is written (Tool.Tests checks the built assembly's).
            Assert.That(Property("Version"), Does.Contain("$(PackageManifestVersion)"));
            Assert.That(project.Descendants("PackageManifest").Select(e => e.Value), Has.All.EndWith("package.json"));
        }

        [Test]
        public void ProjectOpensInUnity2022_3()
        {
            var version = File.ReadAllText(RepositoryPaths.Combine("ProjectSettings", "ProjectVersion.txt"));
            Assert.That(version, Does.Match(@"m_EditorVersion: 2022\.3\.\d+f\d+"));
        }

        [Test]
        public void CoreHasNoEngineReferences()
        {
            var core = Asmdef("Core", "NerfDatasetCreator.Core");
            Assert.That((bool)core["noEngineReferences"], Is.True);
            Assert.That(core["references"].Values<string>(), Is.Empty);
        }

        [Test]
        public void EditorAssemblyIsEditorOnly()
        {
            var editor = Asmdef("Editor", "NerfDatasetCreator.Editor");
            Assert.That(editor["includePlatforms"].Values<string>(), Is.EqualTo(new[] { "Editor" }));
            Assert.That(editor["references"].Values<string>(), Does.Contain("NerfDatasetCreator.Core"));
        }

        [TestCase("Core", "NerfDatasetCreator.Core.Tests")]
        [TestCase("Editor", "NerfDatasetCreator.Editor.Tests")]
        public void TestAssembliesAreTestRunnerAssemblies(string folder, string name)
        {
            var tests = Asmdef(Path.Combine("Tests", folder), name);
            Assert.That(tests["defineConstraints"].Values<string>(), Does.Contain("UNITY_INCLUDE_TESTS"));
            Assert.That((bool)tests["overrideReferences"], Is.True);
            Assert.That(tests["precompiledReferences"].Values<string>(), Does.Contain("nunit.framework.dll"));
            Assert.That(tests["references"].Values<string>(), Is.SupersetOf(new[] { "UnityEngine.TestRunner", "UnityEditor.TestRunner" }));
            Assert.That(tests["includePlatforms"].Values<string>(), Is.EqualTo(new[] { "Editor" }));
        }

        [Test]
        public void EveryAssemblyUsingNewtonsoftReferencesThePrecompiledDll()
        {
            // com.unity.nuget.newtonsoft-json ships a precompiled DLL that is not auto-referenced; an asmdef must
            // name it with overrideReferences, or `using Newtonsoft.Json` fails to compile in Unity.
            foreach (var path in Directory.GetFiles(RepositoryPaths.PluginFolder, "*.asmdef", SearchOption.AllDirectories))
            {
                var folder = Path.GetDirectoryName(path);
                var usesNewtonsoft = Directory.GetFiles(folder, "*.cs", SearchOption.AllDirectories)
                    .Any(f => Regex.IsMatch(File.ReadAllText(f), @"^\s*using\s+Newtonsoft\.Json", RegexOptions.Multiline));
                if (!usesNewtonsoft) continue;
                var asmdef = JObject.Parse(File.ReadAllText(path));
                Assert.That((bool?)asmdef["overrideReferences"], Is.True, path);
                Assert.That(asmdef["precompiledReferences"].Values<string>(), Does.Contain("Newtonsoft.Json.dll"), path);
            }
        }
    }
}
