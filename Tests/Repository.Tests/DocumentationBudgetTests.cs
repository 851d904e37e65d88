using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using System.Xml.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// The user's documentation stays short and complete (issue 33): the README fits a first read, the user pages
    /// (README.md and Documentation~/*.md outside maintainers/) fit a line budget, and every list of the tool's commands
    /// names every command of <see cref="ToolCommands.All"/> — the table the tool's parser and --help use — so a new
    /// command cannot ship unmentioned. A list in a page is the block after a <c>&lt;!-- command list --&gt;</c> line, up to
    /// the next blank line; the package descriptions (package.json, the tool's NuGet package) are lists as a whole.
    /// </summary>
    [TestFixture]
    public class DocumentationBudgetTests
    {
        public const int ReadmeMaxLines = 150;
        public const int UserPagesMaxLines = 3000;
        const string Marker = "<!-- command list -->";

        /// <summary>README.md and every Documentation~/*.md outside maintainers/ (and images/), repository-relative.</summary>
        public static IEnumerable<string> UserPages()
        {
            yield return "README.md";
            foreach (var page in Directory.GetFiles(RepositoryPaths.Combine("Documentation~"), "*.md", SearchOption.TopDirectoryOnly).OrderBy(p => p, StringComparer.Ordinal))
                yield return "Documentation~/" + Path.GetFileName(page);
        }

        static int Lines(string page) => File.ReadAllLines(RepositoryPaths.Combine(page.Split('/'))).Length;

        [Test]
        public void TheReadmeFitsItsBudget()
        {
            Assert.That(Lines("README.md"), Is.LessThanOrEqualTo(ReadmeMaxLines), "README.md: move detail into Documentation~");
        }

        [Test]
        public void TheUserPagesFitTheirBudgetTogether()
        {
            var counts = UserPages().ToDictionary(p => p, Lines);
            var total = counts.Values.Sum();
            TestContext.Progress.WriteLine("user pages: {0} lines ({1})", total, string.Join(", ", counts.Select(c => c.Key + " " + c.Value)));
            Assert.That(total, Is.LessThanOrEqualTo(UserPagesMaxLines),
                "README.md + Documentation~/*.md: move maintainers' detail (sources, design reasons, measurements) into Documentation~/maintainers/");
        }

        [Test]
        public void TheBudgetCountsTheReadmeAndTheUserPagesButNotTheMaintainersPages()
        {
            var pages = UserPages().ToList();
            Assert.That(pages, Does.Contain("README.md").And.Contain("Documentation~/getting-started.md").And.Contain("Documentation~/first-capture.md"));
            Assert.That(pages, Has.None.Contains("maintainers"));
        }

        /// <summary>The tool's command names, from the one table the parser uses.</summary>
        static List<string> Commands() => ToolCommands.All.Select(c => c.Name).ToList();

        /// <summary>The command names of <paramref name="commands"/> that <paramref name="text"/> does not name as a whole word.</summary>
        public static List<string> Missing(string text, IEnumerable<string> commands) =>
            commands.Where(c => !Regex.IsMatch(text, @"(?<![\w-])" + Regex.Escape(c) + @"(?![\w-])")).ToList();

        /// <summary>The blocks that follow each command-list marker of a page.</summary>
        public static List<string> MarkedLists(string markdown)
        {
            var lists = new List<string>();
            var lines = markdown.Replace("\r", "").Split('\n');
            for (var i = 0; i < lines.Length; i++)
            {
                if (lines[i].Trim() != Marker) continue;
                var block = new List<string>();
                for (var j = i + 1; j < lines.Length && lines[j].Trim().Length > 0; j++) block.Add(lines[j]);
                lists.Add(string.Join("\n", block));
            }
            return lists;
        }

        [TestCase("README.md")]
        [TestCase("Documentation~/getting-started.md")]
        [TestCase("Documentation~/settings.md")]
        [TestCase("Documentation~/maintainers/repository-layout.md")]
        public void EveryCommandListOfThePageNamesEveryCommand(string page)
        {
            var lists = MarkedLists(File.ReadAllText(RepositoryPaths.Combine(page.Split('/'))));
            Assert.That(lists, Is.Not.Empty, $"{page}: its list of the tool's commands has no '{Marker}' line before it");
            foreach (var list in lists)
                Assert.That(Missing(list, Commands()), Is.Empty, $"{page}: the command list after '{Marker}' omits these commands:\n{list}");
        }

        [Test]
        public void EveryUserPagesCommandListIsChecked()
        {
            // A marker in a page the case list above forgets would be checked by nothing.
            var marked = UserPages().Where(p => MarkedLists(File.ReadAllText(RepositoryPaths.Combine(p.Split('/')))).Count > 0).ToList();
            Assert.That(marked, Is.EquivalentTo(new[] { "README.md", "Documentation~/getting-started.md", "Documentation~/settings.md" }));
        }

        [Test]
        public void ThePackageDescriptionsNameEveryCommand()
        {
            var manifest = JObject.Parse(File.ReadAllText(RepositoryPaths.Combine("package.json")));
            Assert.That(Missing((string)manifest["description"], Commands()), Is.Empty, "package.json description");
            var project = XDocument.Load(Path.Combine(RepositoryPaths.PluginFolder, "Tools~", "nerf-dataset", "nerf-dataset.csproj"));
            var description = project.Descendants("Description").Single().Value;
            Assert.That(Missing(description, Commands()), Is.Empty, "nerf-dataset.csproj <Description>");
        }

        [Test]
        public void AListMissingACommandIsFound()
        {
            var lists = MarkedLists("intro\n" + Marker + "\n| `plan` | … |\n| `check` | … |\n\nafter: validate");
            Assert.That(lists, Has.Count.EqualTo(1));
            Assert.That(Missing(lists[0], new[] { "plan", "check", "validate" }), Is.EqualTo(new[] { "validate" }));
            Assert.That(Missing("plans, checks and a check-up", new[] { "plan", "check" }), Is.EqualTo(new[] { "plan", "check" }));
        }
    }
}
