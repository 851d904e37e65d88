using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// repository-layout.md's folder maps are the tree: one row per folder under the plugin's Core/ and Editor/, in the
    /// order <c>.ci/layout-map</c> writes them, each saying what it holds. A folder added without a row, a row left for a
    /// removed folder, or a row still reading "TODO" fails here; <c>.ci/layout-map</c> regenerates the rows.
    /// </summary>
    [TestFixture]
    public class LayoutMapTests
    {
        static readonly Regex Row = new Regex(@"^\| `((?:Core|Editor)(?:/[^`]*)?)/` \| (.*) \|$");

        static string Page => RepositoryPaths.Combine("Documentation~", "maintainers", "repository-layout.md");

        /// <summary>The rows between the page's markers for one root, as (folder, description).</summary>
        static List<(string Folder, string Description)> Rows(string root)
        {
            var lines = File.ReadAllLines(Page);
            var begin = Array.IndexOf(lines, $"<!-- layout-map {root} begin -->");
            var end = Array.IndexOf(lines, $"<!-- layout-map {root} end -->");
            Assert.That(begin, Is.GreaterThanOrEqualTo(0), $"repository-layout.md has no '<!-- layout-map {root} begin -->' marker");
            Assert.That(end, Is.GreaterThan(begin), $"repository-layout.md has no '<!-- layout-map {root} end -->' after its begin marker");
            var rows = new List<(string, string)>();
            for (var i = begin + 1; i < end; i++)
            {
                var m = Row.Match(lines[i]);
                if (m.Success) rows.Add((m.Groups[1].Value, m.Groups[2].Value.Trim()));
            }
            return rows;
        }

        /// <summary>The folders Unity imports under Assets/NeRFDatasetCreator/&lt;root&gt;, depth first, siblings in ordinal order
        /// (the order <c>.ci/layout-map</c> writes: Python's sorted() on the names).</summary>
        static List<string> Tree(string root)
        {
            var list = new List<string>();
            void Walk(string relative)
            {
                list.Add(relative);
                var full = Path.Combine(RepositoryPaths.PluginFolder, relative);
                foreach (var child in Directory.GetDirectories(full).Select(Path.GetFileName)
                             .Where(n => !n.EndsWith("~", StringComparison.Ordinal) && !n.StartsWith(".", StringComparison.Ordinal))
                             .OrderBy(n => n, StringComparer.Ordinal))
                    Walk(relative + "/" + child);
            }
            Walk(root);
            return list;
        }

        [TestCase("Core")]
        [TestCase("Editor")]
        public void EveryFolderHasOneRowInTreeOrder(string root)
        {
            var rows = Rows(root).Select(r => r.Folder).ToList();
            var tree = Tree(root);
            Assert.That(tree.Except(rows), Is.Empty, "folders without a row in repository-layout.md (run .ci/layout-map, then describe them)");
            Assert.That(rows.Except(tree), Is.Empty, "rows in repository-layout.md for folders that do not exist (run .ci/layout-map)");
            Assert.That(rows, Is.EqualTo(tree), "repository-layout.md's rows are not in tree order (run .ci/layout-map)");
        }

        [TestCase("Core")]
        [TestCase("Editor")]
        public void EveryRowSaysWhatTheFolderHolds(string root)
        {
            foreach (var (folder, description) in Rows(root))
            {
                Assert.That(description, Is.Not.Empty, folder);
                Assert.That(description, Does.Not.StartWith("TODO"), $"{folder}: describe it in repository-layout.md");
            }
        }
    }
}
