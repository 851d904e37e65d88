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

        AssemblyResult Compile(UnityApi api, string asmdefJson, string code, System.Collections.Generic.IReadOnlyList<PackageStub> stubs = null)
        {
            var sub = Path.Combine(_folder, "A");
            Directory.CreateDirectory(sub);
            File.WriteAllText(Path.Combine(sub, "A.asmdef"), asmdefJson);
            File.WriteAllText(Path.Combine(sub, "A.cs"), code);
            var defs = AssemblyDefinition.FindAll(_folder);
            return AsmdefCompiler.CompileAll(defs, api, stubs)["A"];
        }

        /// <summary>A stub of package com.example.thing at <paramref name="version"/> with assembly Example.Thing.</summary>
        System.Collections.Generic.List<PackageStub> ThingStub(string version)
        {
            var package = Path.Combine(_folder, "stubs", "com.example.thing");
            Directory.CreateDirectory(Path.Combine(package, "Example.Thing"));
            File.WriteAllText(Path.Combine(package, "package.json"), "{ \"name\": \"com.example.thing\", \"version\": \"" + version + "\" }");
            File.WriteAllText(Path.Combine(package, "Example.Thing", "Thing.cs"), "namespace Example { public class Thing : UnityEngine.MonoBehaviour { public int m_Value; } }");
            return PackageStub.FindAll(Path.Combine(_folder, "stubs"));
        }

        const string OptionalAsmdef = "{ \"name\": \"A\", \"references\": [\"Example.Thing\"], \"includePlatforms\": [\"Editor\"], " +
                                      "\"defineConstraints\": [\"HAS_THING\"], \"versionDefines\": [{ \"name\": \"com.example.thing\", " +
                                      "\"expression\": \"[1.0.0,2.0.0)\", \"define\": \"HAS_THING\" }] }";

        [TestCase("2022.3"), TestCase("6000.0")]
        public void AnOptionalAssemblyCompilesAgainstAStubOfItsPackage(string line)
        {
            const string code = "class C { int M(Example.Thing t) => t.m_Value; }";
            Assert.That(Errors(Compile(Line(line), OptionalAsmdef, code, ThingStub("1.1.1"))), Is.Empty);
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void AMemberTheStubDoesNotHaveIsAnError(string line)
        {
            const string code = "class C { int M(Example.Thing t) => t.m_Missing; }";
            Assert.That(Errors(Compile(Line(line), OptionalAsmdef, code, ThingStub("1.1.1"))), Does.Contain("CS1061"));
        }

        [TestCase("2022.3"), TestCase("6000.0")]
        public void WithoutThePackageOrOutsideTheRangeTheDefineIsNotSet(string line)
        {
            const string code = "class C { }";
            Assert.That(Compile(Line(line), OptionalAsmdef, code).Problems, Has.Some.Contains("defineConstraints HAS_THING are not met"));
            Assert.That(Compile(Line(line), OptionalAsmdef, code, ThingStub("2.0.0")).Problems, Has.Some.Contains("defineConstraints HAS_THING are not met"));
        }

        [TestCase("", "0.1.0", true)]
        [TestCase("1.0.0", "1.0.0", true)]
        [TestCase("1.0.0", "0.9.1", false)]
        [TestCase("[1.0.0,2.0.0)", "1.1.1", true)]
        [TestCase("[1.0.0,2.0.0)", "2.0.0", false)]
        [TestCase("(1.0.0,2.0.0]", "1.0.0", false)]
        [TestCase("(1.0.0,2.0.0]", "2.0.0", true)]
        [TestCase("[1.2.0]", "1.2.0", true)]
        [TestCase("[1.0.0,)", "9.0.0", true)]
        [TestCase("[1.0.0,2.0.0)", "1.5.0-preview.3", true)]
        public void VersionDefineExpressionsAreUnitysRanges(string expression, string version, bool admitted)
        {
            Assert.That(VersionRange.Admits(expression, version), Is.EqualTo(admitted));
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
