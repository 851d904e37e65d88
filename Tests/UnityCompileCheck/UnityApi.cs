using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>
    /// Where one editor line's public API comes from: a folder of reference assemblies beside the checkout
    /// (../shared/unity-ref/&lt;line&gt;), or a real Unity install plus a project it has opened.
    /// </summary>
    public sealed class UnityApi
    {
        public string Label { get; private set; }
        public int Major { get; private set; }
        public int Minor { get; private set; }
        /// <summary>The engine's runtime API (what noEngineReferences = false gives every assembly).</summary>
        public IReadOnlyList<string> Engine { get; private set; }
        /// <summary>The editor API, added for assemblies that include only the Editor platform.</summary>
        public IReadOnlyList<string> Editor { get; private set; }
        readonly Func<string, string> _find;

        UnityApi(Func<string, string> find) { _find = find; }

        public override string ToString() => Label;

        /// <summary>The file of an assembly an .asmdef names ("UnityEngine.TestRunner") or lists as precompiled ("nunit.framework.dll"); null when absent.</summary>
        public string Find(string assemblyOrFileName)
        {
            var file = assemblyOrFileName.EndsWith(".dll", StringComparison.OrdinalIgnoreCase) ? assemblyOrFileName : assemblyOrFileName + ".dll";
            return _find(file);
        }

        public static string SharedReferenceRoot(string repositoryRoot) =>
            Path.GetFullPath(Path.Combine(repositoryRoot, "..", "shared", "unity-ref"));

        /// <summary>Every source present on this machine: each line under ../shared/unity-ref, then a real install if one is configured.</summary>
        public static List<UnityApi> Available(string repositoryRoot)
        {
            var list = new List<UnityApi>();
            var shared = SharedReferenceRoot(repositoryRoot);
            if (Directory.Exists(shared))
                foreach (var dir in Directory.GetDirectories(shared).OrderBy(d => d, StringComparer.Ordinal))
                    if (File.Exists(Path.Combine(dir, "UnityEngine.dll")))
                        list.Add(FromReferenceFolder(dir));
            var install = FromEnvironment(repositoryRoot);
            if (install != null) list.Add(install);
            return list;
        }

        public static UnityApi FromReferenceFolder(string dir)
        {
            var line = ParseLine(Path.GetFileName(dir)) ?? throw new ArgumentException("Not a Unity version folder: " + dir);
            // UnityEditor.dll refers to the small build-program data assemblies beside it; Roslyn needs them to bind.
            var editorSupport = Directory.GetFiles(dir, "*.Data.dll").Concat(Directory.GetFiles(dir, "Unity.*.dll"));
            return new UnityApi(file => File.Exists(Path.Combine(dir, file)) ? Path.Combine(dir, file) : null)
            {
                Label = "Unity " + line.Major + "." + line.Minor + " reference assemblies (" + dir + ")",
                Major = line.Major,
                Minor = line.Minor,
                Engine = new[] { Path.Combine(dir, "UnityEngine.dll") },
                Editor = new[] { Path.Combine(dir, "UnityEditor.dll") }.Concat(editorSupport).ToList(),
            };
        }

        /// <summary>
        /// A real install from UNITY_MANAGED_DIR or UNITY_EDITOR_PATH. The Test Framework's assemblies and the
        /// packages' precompiled DLLs live in a project that editor has opened (UNITY_PROJECT_PATH, default: this
        /// repository): Library/ScriptAssemblies and Library/PackageCache.
        /// </summary>
        static UnityApi FromEnvironment(string repositoryRoot)
        {
            var managed = Environment.GetEnvironmentVariable("UNITY_MANAGED_DIR");
            var editorPath = Environment.GetEnvironmentVariable("UNITY_EDITOR_PATH");
            if (string.IsNullOrEmpty(managed) && !string.IsNullOrEmpty(editorPath))
                managed = new[] { "Editor/Data/Managed", "Data/Managed", "Contents/Managed", "Unity.app/Contents/Managed" }
                    .Select(p => Path.Combine(editorPath, p)).FirstOrDefault(Directory.Exists);
            if (string.IsNullOrEmpty(managed))
            {
                if (!string.IsNullOrEmpty(editorPath))
                    throw new InvalidOperationException("UNITY_EDITOR_PATH=" + editorPath + " has no Editor/Data/Managed (or Contents/Managed) folder: point it at a Unity install.");
                return null;
            }
            var modules = Path.Combine(managed, "UnityEngine");
            if (!Directory.Exists(modules))
                throw new InvalidOperationException(managed + " has no UnityEngine folder of module assemblies: point UNITY_MANAGED_DIR at a Unity install's Editor/Data/Managed (Contents/Managed on macOS).");

            var project = Environment.GetEnvironmentVariable("UNITY_PROJECT_PATH");
            if (string.IsNullOrEmpty(project)) project = repositoryRoot;
            var version = Environment.GetEnvironmentVariable("UNITY_VERSION");
            var line = ParseLine(version) ?? ParseLine(managed) ?? ParseLine(ProjectVersion(project))
                ?? throw new InvalidOperationException("Cannot tell the Unity version of " + managed + ": set UNITY_VERSION (e.g. 2022.3.62f1).");
            var all = Directory.GetFiles(modules, "*.dll").OrderBy(f => f, StringComparer.Ordinal).ToList();
            var library = Path.Combine(project, "Library");
            return new UnityApi(file => FindInProject(library, file))
            {
                Label = "Unity " + line.Major + "." + line.Minor + " install (" + managed + "; project " + project + ")",
                Major = line.Major,
                Minor = line.Minor,
                Engine = all.Where(f => Path.GetFileName(f).StartsWith("UnityEngine", StringComparison.Ordinal)).ToList(),
                Editor = all.Where(f => Path.GetFileName(f).StartsWith("UnityEditor", StringComparison.Ordinal)).ToList(),
            };
        }

        static string FindInProject(string library, string file)
        {
            var scripts = Path.Combine(library, "ScriptAssemblies", file);
            if (File.Exists(scripts)) return scripts;
            var cache = Path.Combine(library, "PackageCache");
            if (!Directory.Exists(cache)) return null;
            var hits = Directory.GetFiles(cache, file, SearchOption.AllDirectories).OrderBy(f => f, StringComparer.Ordinal).ToList();
            // com.unity.ext.nunit ships several builds; the Test Runner compiles against the unity-custom one.
            return hits.FirstOrDefault(h => h.Replace('\\', '/').Contains("/unity-custom/")) ?? hits.FirstOrDefault();
        }

        static string ProjectVersion(string project)
        {
            var path = Path.Combine(project, "ProjectSettings", "ProjectVersion.txt");
            return File.Exists(path) ? File.ReadAllText(path) : null;
        }

        static (int Major, int Minor)? ParseLine(string text)
        {
            if (string.IsNullOrEmpty(text)) return null;
            var m = Regex.Match(text, @"(20[1-9][0-9]|[6-9][0-9]{3})\.([0-9]+)");
            if (!m.Success) return null;
            return (int.Parse(m.Groups[1].Value), int.Parse(m.Groups[2].Value));
        }
    }
}
