using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>
    /// A third-party package the plugin supports without depending on it (e.g. aras-p's Gaussian Splatting): under
    /// PackageStubs/&lt;package name&gt;/ a package.json (name, version) and one folder per assembly the package has, named as
    /// that assembly, holding only the public signatures the plugin uses, each cited to the package's source. The check
    /// sets an asmdef's <c>versionDefines</c> for a stubbed package as Unity would for the installed package, and compiles
    /// a reference to a stubbed assembly against the stub. What this proves: the optional code calls members with these
    /// names and signatures; that the stub matches the real package is only as good as its citations.
    /// </summary>
    public sealed class PackageStub
    {
        public string Name { get; private set; }
        public string Version { get; private set; }
        public IReadOnlyList<Assembly> Assemblies { get; private set; }

        public sealed class Assembly
        {
            public string Name { get; set; }
            public IReadOnlyList<string> Sources { get; set; }
        }

        public static string Folder(string repositoryRoot) => Path.Combine(repositoryRoot, "Tests", "UnityCompileCheck", "PackageStubs");

        public static List<PackageStub> FindAll(string folder)
        {
            var stubs = new List<PackageStub>();
            if (!Directory.Exists(folder)) return stubs;
            foreach (var dir in Directory.GetDirectories(folder).OrderBy(d => d, StringComparer.Ordinal))
            {
                var manifest = Path.Combine(dir, "package.json");
                if (!File.Exists(manifest)) continue;
                using var doc = JsonDocument.Parse(File.ReadAllText(manifest));
                stubs.Add(new PackageStub
                {
                    Name = doc.RootElement.GetProperty("name").GetString(),
                    Version = doc.RootElement.GetProperty("version").GetString(),
                    Assemblies = Directory.GetDirectories(dir).OrderBy(d => d, StringComparer.Ordinal)
                        .Select(d => new Assembly
                        {
                            Name = Path.GetFileName(d),
                            Sources = Directory.GetFiles(d, "*.cs", SearchOption.AllDirectories).OrderBy(f => f, StringComparer.Ordinal).ToList(),
                        })
                        .Where(a => a.Sources.Count > 0).ToList(),
                });
            }
            return stubs;
        }
    }

    /// <summary>
    /// Unity's version-define expressions (Unity Manual, "Assembly definition properties", Version Defines): empty admits any
    /// version, "x.y.z" means x.y.z or later, "[a,b]", "[a,b)", "(a,b]", "(a,b)" are intervals (an empty bound is open).
    /// </summary>
    public static class VersionRange
    {
        public static bool Admits(string expression, string version)
        {
            var v = Parse(version);
            if (v == null) return false;
            expression = (expression ?? "").Trim();
            if (expression.Length == 0) return true;
            if (expression[0] != '[' && expression[0] != '(')
                return Parse(expression) is Version min && v >= min;
            var close = expression[expression.Length - 1];
            var parts = expression.Substring(1, expression.Length - 2).Split(',');
            if (parts.Length == 1) return Parse(parts[0]) is Version exact && expression[0] == '[' && close == ']' && v == exact;
            if (parts.Length != 2) return false;
            var low = Parse(parts[0]);
            var high = Parse(parts[1]);
            if (low != null && (expression[0] == '[' ? v < low : v <= low)) return false;
            if (high != null && (close == ']' ? v > high : v >= high)) return false;
            return true;
        }

        static Version Parse(string text)
        {
            text = (text ?? "").Trim();
            var dash = text.IndexOfAny(new[] { '-', '+' }); // pre-release and build suffixes are ignored here
            if (dash >= 0) text = text.Substring(0, dash);
            return Version.TryParse(text, out var v) ? v : null;
        }
    }
}
