using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>The README's window diagram names the same numbered steps as window.md, so neither can drift alone.</summary>
    [TestFixture]
    public class WindowDiagramTests
    {
        [Test]
        public void TheDiagramShowsTheStepsWindowMdDescribes()
        {
            var page = File.ReadAllText(RepositoryPaths.Combine("Documentation~", "window.md"));
            var steps = Regex.Matches(page, @"^## (\d) (.+?)\s*$", RegexOptions.Multiline).Select(m => m.Groups[1].Value + " " + m.Groups[2].Value).ToList();
            Assert.That(steps, Has.Count.EqualTo(7), "window.md's numbered steps");

            var svg = File.ReadAllText(RepositoryPaths.Combine("Documentation~", "images", "window-and-preview.svg"));
            var drawn = Regex.Matches(svg, @"font-size=""13"">(\d)  ([^<]+)</text>").Select(m => m.Groups[1].Value + " " + m.Groups[2].Value).ToList();
            Assert.That(drawn, Is.EqualTo(steps));
        }
    }
}
