using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>The outcome of compiling one .asmdef against one Unity API.</summary>
    sealed class AssemblyResult
    {
        public AssemblyDefinition Definition;
        public IReadOnlyList<Diagnostic> Diagnostics;
        public IReadOnlyList<string> Problems = Array.Empty<string>();
        public Compilation Compilation;
        public IEnumerable<Diagnostic> Errors => Diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error);
    }

    /// <summary>
    /// Compiles .asmdef assemblies as Unity's editor does: C# 9, the editor line's defines, and exactly the
    /// references each .asmdef declares (other .asmdefs by name or GUID, Unity's Test Framework assemblies, the listed
    /// precompiled DLLs, UnityEngine unless noEngineReferences, UnityEditor for Editor-only assemblies) on top of the
    /// .NET Standard 2.1 API.
    /// </summary>
    static class AsmdefCompiler
    {
        public static string NetStandardReferenceDir =>
            typeof(AsmdefCompiler).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>()
                .First(a => a.Key == "NetStandardReferenceDir").Value;

        static IReadOnlyList<MetadataReference> _baseReferences;

        static IReadOnlyList<MetadataReference> BaseReferences =>
            _baseReferences ??= Directory.GetFiles(NetStandardReferenceDir, "*.dll")
                .OrderBy(f => f, StringComparer.Ordinal)
                .Select(f => (MetadataReference)MetadataReference.CreateFromFile(f)).ToList();

        /// <summary>A plugin DLL named <paramref name="dll"/> under the Assets folder that holds <paramref name="folder"/>, or null.</summary>
        static string ShippedPlugin(string folder, string dll)
        {
            var dir = new DirectoryInfo(folder);
            while (dir != null && dir.Name != "Assets") dir = dir.Parent;
            if (dir == null) return null;
            return Directory.GetFiles(dir.FullName, dll, SearchOption.AllDirectories).Where(f => !f.Contains("~" + Path.DirectorySeparatorChar)).OrderBy(f => f, StringComparer.Ordinal).FirstOrDefault();
        }

        /// <summary>Compiles every definition in dependency order; a definition whose references failed is still compiled against what exists.</summary>
        public static Dictionary<string, AssemblyResult> CompileAll(IReadOnlyList<AssemblyDefinition> definitions, UnityApi api,
            IReadOnlyList<PackageStub> stubs = null)
        {
            stubs = stubs ?? Array.Empty<PackageStub>();
            var stubAssemblies = new Dictionary<string, MetadataReference>(StringComparer.Ordinal);
            var results = new Dictionary<string, AssemblyResult>(StringComparer.Ordinal);
            var byName = definitions.ToDictionary(d => d.Name, StringComparer.Ordinal);
            var byGuid = definitions.Where(d => d.Guid != null).ToDictionary(d => "GUID:" + d.Guid, d => d.Name, StringComparer.OrdinalIgnoreCase);
            var visiting = new HashSet<string>(StringComparer.Ordinal);

            AssemblyResult Compile(AssemblyDefinition def)
            {
                if (results.TryGetValue(def.Name, out var done)) return done;
                if (!visiting.Add(def.Name)) throw new InvalidOperationException("Assembly definitions reference each other in a cycle through " + def.Name);
                var problems = new List<string>();
                var references = new List<MetadataReference>(BaseReferences);
                var defines = UnityDefines.ForEditor(api.Major, api.Minor);
                // versionDefines: as Unity sets them for an installed package; here the packages are the stubs present.
                foreach (var (package, expression, define) in def.VersionDefines)
                {
                    var stub = stubs.FirstOrDefault(p => p.Name == package);
                    if (stub != null && VersionRange.Admits(expression, stub.Version) && !defines.Contains(define)) defines.Add(define);
                }
                if (def.IncludePlatforms.Count > 0 && !def.IsEditorOnly)
                    problems.Add("includePlatforms " + string.Join(",", def.IncludePlatforms) + ": only Editor-only assemblies are checked here");
                if (!def.NoEngineReferences)
                {
                    references.AddRange(api.Engine.Select(f => MetadataReference.CreateFromFile(f)));
                    if (def.IsEditorOnly) references.AddRange(api.Editor.Select(f => MetadataReference.CreateFromFile(f)));
                }
                foreach (var reference in def.References)
                {
                    var name = byGuid.TryGetValue(reference, out var n) ? n : reference;
                    if (byName.TryGetValue(name, out var dependency))
                    {
                        references.Add(Compile(dependency).Compilation.ToMetadataReference());
                        continue;
                    }
                    var stubbed = stubs.SelectMany(p => p.Assemblies).FirstOrDefault(a => a.Name == name);
                    if (stubbed != null)
                    {
                        if (!stubAssemblies.TryGetValue(name, out var compiled))
                            stubAssemblies[name] = compiled = CompileStub(stubbed, api).ToMetadataReference();
                        references.Add(compiled);
                        continue;
                    }
                    var file = api.Find(name);
                    if (file == null) problems.Add("reference '" + reference + "' is neither an .asmdef here nor an assembly of " + api.Label);
                    else references.Add(MetadataReference.CreateFromFile(file));
                }
                if (!def.OverrideReferences && def.PrecompiledReferences.Count > 0)
                    problems.Add("precompiledReferences are listed but overrideReferences is false, so Unity ignores the list");
                foreach (var dll in def.PrecompiledReferences)
                {
                    // Unity resolves precompiledReferences against every plugin DLL of the project, the package's own
                    // included (2022.3 EditorBuildRules.cs:419–435), so a DLL shipped in the package is found there too.
                    var file = api.Find(dll) ?? ShippedPlugin(def.Folder, dll);
                    if (file == null) problems.Add("precompiled reference '" + dll + "' is not in " + api.Label + " nor shipped under Assets");
                    else references.Add(MetadataReference.CreateFromFile(file));
                }
                var unmet = def.DefineConstraints.Where(c => !defines.Contains(c.TrimStart('!')) ^ c.StartsWith("!", StringComparison.Ordinal)).ToList();
                if (unmet.Count > 0)
                    problems.Add("defineConstraints " + string.Join(",", unmet) + " are not met, so Unity would not compile this assembly");

                var parse = new CSharpParseOptions(LanguageVersion.CSharp9, preprocessorSymbols: defines);
                var trees = def.Sources.Select(path => CSharpSyntaxTree.ParseText(File.ReadAllText(path), parse, path)).ToList();
                var options = new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary,
                    allowUnsafe: def.AllowUnsafeCode, nullableContextOptions: NullableContextOptions.Disable,
                    // Unity's compiler settles binding conflicts between its assemblies the same way.
                    assemblyIdentityComparer: DesktopAssemblyIdentityComparer.Default)
                    // Unified-version notices (netstandard 2.0 → 2.1) that csc hides by default and Unity too.
                    .WithSpecificDiagnosticOptions(new Dictionary<string, ReportDiagnostic>
                    {
                        ["CS1701"] = ReportDiagnostic.Suppress,
                        ["CS1702"] = ReportDiagnostic.Suppress,
                    });
                var compilation = CSharpCompilation.Create(def.Name, trees, references, options);
                var result = new AssemblyResult
                {
                    Definition = def,
                    Compilation = compilation,
                    Diagnostics = compilation.GetDiagnostics().Where(d => d.Severity >= DiagnosticSeverity.Warning).ToList(),
                    Problems = problems,
                };
                visiting.Remove(def.Name);
                results[def.Name] = result;
                return result;
            }

            foreach (var def in definitions) Compile(def);
            return results;
        }

        /// <summary>A package stub's assembly: its sources against the engine API (runtime assemblies, as the stubbed ones are).</summary>
        public static CSharpCompilation CompileStub(PackageStub.Assembly stub, UnityApi api)
        {
            var parse = new CSharpParseOptions(LanguageVersion.CSharp9, preprocessorSymbols: UnityDefines.ForEditor(api.Major, api.Minor));
            var references = new List<MetadataReference>(BaseReferences);
            references.AddRange(api.Engine.Select(f => MetadataReference.CreateFromFile(f)));
            var options = new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, nullableContextOptions: NullableContextOptions.Disable,
                assemblyIdentityComparer: DesktopAssemblyIdentityComparer.Default)
                .WithSpecificDiagnosticOptions(new Dictionary<string, ReportDiagnostic> { ["CS1701"] = ReportDiagnostic.Suppress, ["CS1702"] = ReportDiagnostic.Suppress });
            return CSharpCompilation.Create(stub.Name, stub.Sources.Select(p => CSharpSyntaxTree.ParseText(File.ReadAllText(p), parse, p)), references, options);
        }

        public static string Describe(Diagnostic d, string root) =>
            Where(d.Location, root) + ": " + d.Severity.ToString().ToLowerInvariant() + " " + d.Id + ": " +
            d.GetMessage(System.Globalization.CultureInfo.InvariantCulture);

        /// <summary>"path(line,column)" relative to the repository.</summary>
        public static string Where(Location location, string root)
        {
            var span = location.GetMappedLineSpan();
            var path = span.Path ?? "";
            if (path.StartsWith(root, StringComparison.Ordinal)) path = path.Substring(root.Length).TrimStart('/', '\\');
            return path + "(" + (span.StartLinePosition.Line + 1) + "," + (span.StartLinePosition.Character + 1) + ")";
        }
    }
}
