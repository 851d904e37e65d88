using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>
    /// The check itself can fail: wrong members, engine calls from an engine-free assembly, an API of a later
    /// line and a missing reference are errors, against each editor line present.
    /// </summary>
    [TestFixture]
    public class CompileCheckSelfTests
    {
        string _folder;

        [SetUp]
        public void SetUp()
        {
            _folder = Path.Combine(Path.GetTempPath(), "unity-compile-check-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_folder);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(_folder, true);

        static UnityApi Line(string line)
        {
            var dir = Path.Combine(UnityApi.SharedReferenceRoot(RepositoryRoot.Path), line);
            if (!File.Exists(Path.Combine(dir, "UnityEngine.dll"))) Assert.Ignore("No Unity " + line + " reference assemblies at " + dir);
            return UnityApi.FromReferenceFolder(dir);
        }

        AssemblyResult Compile(UnityApi api, string asmdefJson, string code)
        {
            var sub = Path.Combine(_folder, "A");
            Directory.CreateDirectory(sub);
            File.WriteAllText(Path.Combine(sub, "A.asmdef"), asmdefJson);
            File.WriteAllText(Path.Combine(sub, "A.cs"), code);
            var defs = AssemblyDefinition.FindAll(_folder);
            return AsmdefCompiler.CompileAll(defs, api)["A"];
        }

        const string EditorAsmdef = "{ \"name\": \"A\", \"includePlatforms\": [\"Editor\"] }";

        static string[] Errors(AssemblyResult r) => r.Errors.Select(d => d.Id).Concat(r.Problems).ToArray();

        [TestCase("2022.3"), TestCase("6000.0")]
        public void ACorrectEditorCallCompiles(string line)
        {
            var r = Compile(Line(line), EditorAsmdef,
                "class C { void M() { UnityEditor.EditorUtility.DisplayProgressBar(\"a\", \"b\", 0.5f); var c = new UnityEngine.Camera(); c.Render(); } }");
            Assert.That(Errors(r), Is.Empty);
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void AnUnknownMemberIsAnError(string line)
        {
            var r = Compile(Line(line), EditorAsmdef, "class C { void M(UnityEngine.Camera c) { c.RenderEverythingTwice(); } }");
            Assert.That(Errors(r), Does.Contain("CS1061"));
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void AnEngineFreeAssemblyCannotUseTheEngine(string line)
        {
            var r = Compile(Line(line), "{ \"name\": \"A\", \"includePlatforms\": [\"Editor\"], \"noEngineReferences\": true }",
                "class C { UnityEngine.Vector3 v; }");
            Assert.That(Errors(r), Does.Contain("CS0246"));
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void ARuntimeAssemblyCannotUseTheEditor(string line)
        {
            var r = Compile(Line(line), "{ \"name\": \"A\", \"includePlatforms\": [] }",
                "class C { void M() { UnityEditor.EditorUtility.ClearProgressBar(); } }");
            Assert.That(Errors(r), Does.Contain("CS0234"), "the UnityEditor namespace is unknown outside Editor-only assemblies");
        }

        [Test]
        public void AnApiOfALaterLineFailsOnTheEarlierOne()
        {
            const string code = "using UnityEngine; using UnityEngine.Experimental.Rendering; " +
                                "class C { bool M() => SystemInfo.IsFormatSupported(GraphicsFormat.R8G8B8A8_SRGB, GraphicsFormatUsage.Render); }";
            Assert.That(Errors(Compile(Line("6000.0"), EditorAsmdef, code)), Is.Empty);
            Assert.That(Errors(Compile(Line("2022.3"), EditorAsmdef, code)), Is.Not.Empty);
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void TheVersionDefinesSelectTheRightBranch(string line)
        {
            const string code = "using UnityEngine; using UnityEngine.Experimental.Rendering; class C { bool M() {\n" +
                                "#if UNITY_2023_2_OR_NEWER\n return SystemInfo.IsFormatSupported(GraphicsFormat.R8_UNorm, GraphicsFormatUsage.Render);\n" +
                                "#else\n return SystemInfo.IsFormatSupported(GraphicsFormat.R8_UNorm, FormatUsage.Render);\n#endif\n } }";
            var r = Compile(Line(line), EditorAsmdef, code);
            Assert.That(Errors(r), Is.Empty);
            Assert.That(r.Diagnostics, Is.Empty, "an obsolete API on either branch would warn");
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void TestsNeedTheTestRunnerReferenceForLogAssert(string line)
        {
            const string code = "using UnityEngine.TestTools; using NUnit.Framework; class T { [Test] public void M() { LogAssert.NoUnexpectedReceived(); } }";
            var without = Compile(Line(line), "{ \"name\": \"A\", \"includePlatforms\": [\"Editor\"], \"overrideReferences\": true, \"precompiledReferences\": [\"nunit.framework.dll\"] }", code);
            Assert.That(Errors(without), Is.Not.Empty);
            var with = Compile(Line(line), "{ \"name\": \"A\", \"references\": [\"UnityEngine.TestRunner\"], \"includePlatforms\": [\"Editor\"], \"overrideReferences\": true, \"precompiledReferences\": [\"nunit.framework.dll\"] }", code);
            Assert.That(Errors(with), Is.Empty);
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void AnAssemblyThatIsNotThereIsNamed(string line)
        {
            var r = Compile(Line(line), "{ \"name\": \"A\", \"references\": [\"Unity.Nonexistent\"], \"includePlatforms\": [\"Editor\"] }", "class C {}");
            Assert.That(r.Problems.Single(), Does.Contain("Unity.Nonexistent"));
        }
    }
}
