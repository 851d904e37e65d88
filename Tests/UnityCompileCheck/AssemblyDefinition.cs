using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>One .asmdef and the C# files Unity compiles into it.</summary>
    sealed class AssemblyDefinition
    {
        public string Name { get; private set; }
        public string Folder { get; private set; }
        public string Guid { get; private set; }
        public IReadOnlyList<string> References { get; private set; }
        public IReadOnlyList<string> PrecompiledReferences { get; private set; }
        public IReadOnlyList<string> IncludePlatforms { get; private set; }
        public IReadOnlyList<string> DefineConstraints { get; private set; }
        /// <summary>versionDefines: a symbol set when a package (name) is installed at a version the expression admits.</summary>
        public IReadOnlyList<(string Package, string Expression, string Define)> VersionDefines { get; private set; }
        public bool OverrideReferences { get; private set; }
        public bool NoEngineReferences { get; private set; }
        public bool AllowUnsafeCode { get; private set; }
        public IReadOnlyList<string> Sources { get; set; }

        public bool IsEditorOnly => IncludePlatforms.Count == 1 && IncludePlatforms[0] == "Editor";

        public static AssemblyDefinition Read(string path)
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(path),
                new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
            var root = doc.RootElement;
            return new AssemblyDefinition
            {
                Name = root.GetProperty("name").GetString(),
                Folder = Path.GetDirectoryName(path),
                Guid = MetaGuid(path + ".meta"),
                References = Strings(root, "references"),
                PrecompiledReferences = Strings(root, "precompiledReferences"),
                IncludePlatforms = Strings(root, "includePlatforms"),
                DefineConstraints = Strings(root, "defineConstraints"),
                VersionDefines = root.TryGetProperty("versionDefines", out var v) && v.ValueKind == JsonValueKind.Array
                    ? v.EnumerateArray().Select(e => (Text(e, "name"), Text(e, "expression"), Text(e, "define"))).ToList()
                    : new List<(string, string, string)>(),
                OverrideReferences = Bool(root, "overrideReferences"),
                NoEngineReferences = Bool(root, "noEngineReferences"),
                AllowUnsafeCode = Bool(root, "allowUnsafeCode"),
            };
        }

        /// <summary>
        /// Every .asmdef under <paramref name="assetsFolder"/>, each with the .cs files of its folder tree minus the
        /// sub-trees another .asmdef owns. Like Unity's importer, folders ending in '~' or starting with '.' are skipped.
        /// </summary>
        public static List<AssemblyDefinition> FindAll(string assetsFolder)
        {
            var defs = new List<AssemblyDefinition>();
            var owned = new List<(string Folder, List<string> Files)>();
            Walk(new DirectoryInfo(assetsFolder), null, defs, owned);
            foreach (var def in defs)
                def.Sources = owned.First(o => o.Folder == def.Folder).Files.OrderBy(f => f, StringComparer.Ordinal).ToList();
            return defs;
        }

        static void Walk(DirectoryInfo dir, List<string> current, List<AssemblyDefinition> defs, List<(string, List<string>)> owned)
        {
            if (dir.Name.EndsWith("~", StringComparison.Ordinal) || dir.Name.StartsWith(".", StringComparison.Ordinal)) return;
            var asmdef = dir.GetFiles("*.asmdef").FirstOrDefault();
            if (asmdef != null)
            {
                var def = Read(asmdef.FullName);
                defs.Add(def);
                current = new List<string>();
                owned.Add((def.Folder, current));
            }
            if (current != null)
                current.AddRange(dir.GetFiles("*.cs").Select(f => f.FullName));
            foreach (var sub in dir.GetDirectories().OrderBy(d => d.Name, StringComparer.Ordinal))
                Walk(sub, current, defs, owned);
        }

        static IReadOnlyList<string> Strings(JsonElement root, string key) =>
            root.TryGetProperty(key, out var a) && a.ValueKind == JsonValueKind.Array
                ? a.EnumerateArray().Select(e => e.GetString()).ToList()
                : new List<string>();

        static string Text(JsonElement e, string key) =>
            e.TryGetProperty(key, out var t) && t.ValueKind == JsonValueKind.String ? t.GetString() : "";

        static bool Bool(JsonElement root, string key) =>
            root.TryGetProperty(key, out var b) && b.ValueKind == JsonValueKind.True;

        static string MetaGuid(string metaPath)
        {
            if (!File.Exists(metaPath)) return null;
            foreach (var line in File.ReadLines(metaPath))
                if (line.StartsWith("guid: ", StringComparison.Ordinal))
                    return line.Substring(6).Trim();
            return null;
        }
    }
}
