using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>
    /// Every .asmdef of the repository, compiled against every Unity API present on this machine: one test per
    /// (editor line, assembly). On a machine with neither ../shared/unity-ref nor a Unity install one test says so
    /// and is skipped, or fails where UNITY_COMPILE_CHECK=required (CI).
    /// </summary>
    [TestFixture]
    public class UnityCompileCheckTests
    {
        static readonly Dictionary<string, Dictionary<string, AssemblyResult>> Cache = new Dictionary<string, Dictionary<string, AssemblyResult>>();

        static string Root => RepositoryRoot.Path;

        /// <summary>The third-party packages optional assemblies are checked against (<see cref="PackageStub"/>).</summary>
        static List<PackageStub> Stubs => PackageStub.FindAll(PackageStub.Folder(Root));

        static IEnumerable<TestCaseData> Cases()
        {
            var apis = UnityApi.Available(Root);
            var definitions = AssemblyDefinition.FindAll(Path.Combine(Root, "Assets"));
            foreach (var api in apis)
                foreach (var def in definitions)
                    yield return new TestCaseData(api, def.Name)
                        .SetName("Unity " + api.Major + "." + api.Minor + (api.Label.Contains(" install ") ? " install" : "") + " compiles " + def.Name);
        }

        [Test]
        public void AUnityApiIsAvailableToCompileAgainst()
        {
            var apis = UnityApi.Available(Root);
            TestContext.Progress.WriteLine("Unity compile check against: " + (apis.Count == 0 ? "nothing" : string.Join("; ", apis.Select(a => a.Label))));
            if (apis.Count > 0) return;
            var message = "No Unity API on this machine (neither " + UnityApi.SharedReferenceRoot(Root) +
                          "/<line> nor UNITY_EDITOR_PATH / UNITY_MANAGED_DIR): the Unity layer was not compiled.";
            // CI sets UNITY_COMPILE_CHECK=required, so a lost reference folder there is a failure, not a skip.
            if (Environment.GetEnvironmentVariable("UNITY_COMPILE_CHECK") == "required") Assert.Fail(message);
            Assert.Ignore(message);
        }

        [Test]
        public void EveryPluginAssemblyHasAnAsmdefHere()
        {
            var names = AssemblyDefinition.FindAll(Path.Combine(Root, "Assets")).Select(d => d.Name).ToList();
            Assert.That(names, Is.SupersetOf(new[]
            {
                "NerfDatasetCreator.Core", "NerfDatasetCreator.Editor", "NerfDatasetCreator.Core.Tests", "NerfDatasetCreator.Editor.Tests",
            }));
        }

        [TestCaseSource(nameof(Cases))]
        public void Compiles(UnityApi api, string assembly)
        {
            if (!Cache.TryGetValue(api.Label, out var results))
                Cache[api.Label] = results = AsmdefCompiler.CompileAll(AssemblyDefinition.FindAll(Path.Combine(Root, "Assets")), api, Stubs);
            var result = results[assembly];
            Assert.That(result.Definition.Sources, Is.Not.Empty, assembly + " has no C# files");
            var errors = result.Errors.Select(d => AsmdefCompiler.Describe(d, Root)).ToList();
            var warnings = result.Diagnostics.Where(d => d.Severity == Microsoft.CodeAnalysis.DiagnosticSeverity.Warning)
                .Select(d => AsmdefCompiler.Describe(d, Root)).ToList();
            foreach (var w in warnings) TestContext.WriteLine(w);
            Assert.That(result.Problems.Concat(errors).ToList(), Is.Empty,
                assembly + " does not compile against " + api.Label + ":\n" + string.Join("\n", result.Problems.Concat(errors)));
            Assert.That(warnings, Is.Empty, assembly + " compiles against " + api.Label + " with warnings Unity would print:\n" + string.Join("\n", warnings));
        }
    
        /// <summary>Every package stub compiles on its own against each editor line (a stub that does not could hide nothing).</summary>
        [Test]
        public void EveryPackageStubCompiles()
        {
            var stubs = Stubs;
            Assert.That(stubs.Select(s => s.Name), Does.Contain("org.nesnausk.gaussian-splatting"));
            var apis = UnityApi.Available(Root);
            if (apis.Count == 0) Assert.Ignore("No Unity API on this machine.");
            foreach (var api in apis)
                foreach (var assembly in stubs.SelectMany(s => s.Assemblies))
                {
                    var errors = AsmdefCompiler.CompileStub(assembly, api).GetDiagnostics()
                        .Where(d => d.Severity >= Microsoft.CodeAnalysis.DiagnosticSeverity.Warning).Select(d => AsmdefCompiler.Describe(d, Root)).ToList();
                    Assert.That(errors, Is.Empty, assembly.Name + " against " + api.Label);
                }
        }

        /// <summary>
        /// Unity drops the types of a disabled built-in module, so package.json declares every module the Unity layer
        /// and its tests use, and the development project enables them.
        /// </summary>
        [Test]
        public void PackageJsonDeclaresEveryBuiltInModuleItUses()
        {
            var api = UnityApi.Available(Root).FirstOrDefault();
            if (api == null) Assert.Ignore("No Unity API on this machine to bind the Unity layer's types.");
            if (!Cache.TryGetValue(api.Label, out var results))
                Cache[api.Label] = results = AsmdefCompiler.CompileAll(AssemblyDefinition.FindAll(Path.Combine(Root, "Assets")), api, Stubs);
            var used = new SortedDictionary<string, string>(StringComparer.Ordinal);
            foreach (var result in results.Values.Where(r => !r.Definition.NoEngineReferences))
                foreach (var pair in BuiltInModules.UsedBy(result.Compilation, Root))
                    if (!used.ContainsKey(pair.Key)) used[pair.Key] = pair.Value;
            TestContext.WriteLine(string.Join("\n", used.Select(p => p.Key + ": " + p.Value)));

            var package = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(Path.Combine(Root, "package.json")));
            var project = Newtonsoft.Json.Linq.JObject.Parse(File.ReadAllText(Path.Combine(Root, "Packages", "manifest.json")));
            var undeclared = used.Where(p => package["dependencies"]?[p.Key] == null).Select(p => p.Key + " (" + p.Value + ")").ToList();
            var disabled = used.Where(p => project["dependencies"]?[p.Key] == null).Select(p => p.Key + " (" + p.Value + ")").ToList();
            Assert.That(undeclared, Is.Empty, "package.json does not declare these built-in modules");
            Assert.That(disabled, Is.Empty, "Packages/manifest.json does not enable these built-in modules");
        }
    }
}
