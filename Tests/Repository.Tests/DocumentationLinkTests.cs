using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// Every relative link of the README, Documentation~ and the sample's README leads to a file that exists and, with
    /// a <c>#fragment</c>, to a heading of that page, by GitHub's rule for heading anchors (lower case; punctuation
    /// other than '-' and '_' dropped; each space a '-'; a repeated heading gets -1, -2 …).
    /// </summary>
    [TestFixture]
    public class DocumentationLinkTests
    {
        static readonly Regex Link = new Regex(@"\]\(([^)\s]+)\)");

        static IEnumerable<string> Pages()
        {
            yield return "README.md";
            foreach (var folder in new[] { "Documentation~", Path.Combine("Assets", "Samples") })
                foreach (var page in Directory.GetFiles(RepositoryPaths.Combine(folder), "*.md", SearchOption.AllDirectories).OrderBy(p => p, StringComparer.Ordinal))
                    yield return Path.GetRelativePath(RepositoryPaths.Root, page).Replace('\\', '/');
        }

        /// <summary>The page's text outside fenced code blocks, line by line.</summary>
        static IEnumerable<string> ProseLines(string path)
        {
            var inside = false;
            foreach (var line in File.ReadAllLines(path))
            {
                if (line.TrimStart().StartsWith("```", StringComparison.Ordinal)) { inside = !inside; continue; }
                if (!inside) yield return line;
            }
        }

        public static string Anchor(string heading)
        {
            var text = Regex.Replace(heading, @"\[([^\]]*)\]\([^)]*\)", "$1").Replace("`", "").Replace("*", "").Trim().ToLowerInvariant();
            var slug = new StringBuilder();
            foreach (var c in text)
            {
                if (char.IsLetterOrDigit(c) || c == '-' || c == '_') slug.Append(c);
                else if (c == ' ') slug.Append('-');
            }
            return slug.ToString();
        }

        static HashSet<string> Anchors(string path)
        {
            var seen = new Dictionary<string, int>();
            var anchors = new HashSet<string>();
            foreach (var line in ProseLines(path))
            {
                var heading = Regex.Match(line, @"^#{1,6}\s+(.*?)\s*#*\s*$");
                if (!heading.Success) continue;
                var anchor = Anchor(heading.Groups[1].Value);
                seen.TryGetValue(anchor, out var count);
                anchors.Add(count == 0 ? anchor : anchor + "-" + count);
                seen[anchor] = count + 1;
            }
            return anchors;
        }

        [TestCaseSource(nameof(Pages))]
        public void EveryRelativeLinkLeadsToAFileAndHeadingThatExist(string page)
        {
            var path = RepositoryPaths.Combine(page.Split('/'));
            var broken = new List<string>();
            foreach (var line in ProseLines(path))
                foreach (Match match in Link.Matches(line))
                {
                    var target = match.Groups[1].Value;
                    if (Regex.IsMatch(target, @"^[a-z][a-z0-9+.-]*:", RegexOptions.IgnoreCase)) continue; // http:, https:, mailto:
                    var hash = target.IndexOf('#');
                    var file = hash < 0 ? target : target.Substring(0, hash);
                    var fragment = hash < 0 ? "" : target.Substring(hash + 1);
                    var resolved = file.Length == 0 ? path : Path.GetFullPath(Path.Combine(Path.GetDirectoryName(path), Uri.UnescapeDataString(file)));
                    if (!File.Exists(resolved) && !Directory.Exists(resolved)) { broken.Add(target + " (no such file)"); continue; }
                    if (fragment.Length > 0 && resolved.EndsWith(".md", StringComparison.Ordinal) && !Anchors(resolved).Contains(fragment))
                        broken.Add(target + " (no such heading)");
                }
            Assert.That(broken, Is.Empty, page);
        }

        [TestCase("Installing", "installing")]
        [TestCase("2. `nerf-dataset convert <dir> --to nerfstudio|colmap|ngp|dynamic3dgs [--depths]`", "2-nerf-dataset-convert-dir---to-nerfstudiocolmapngpdynamic3dgs---depths")]
        [TestCase("Worked example: the sample's animated target", "worked-example-the-samples-animated-target")]
        [TestCase("3. `points3d.ply` — the initial cloud for Gaussian Splatting", "3-points3dply--the-initial-cloud-for-gaussian-splatting")]
        public void AnchorsFollowGitHubsRule(string heading, string anchor)
        {
            Assert.That(Anchor(heading), Is.EqualTo(anchor));
        }

        [Test]
        public void TheCheckSeesTheLinksOfEveryDocumentationPage()
        {
            Assert.That(Pages(), Does.Contain("Documentation~/settings.md").And.Contain("README.md").And.Contain("Assets/Samples/NeRFSample/README.md"));
        }
    }
}
