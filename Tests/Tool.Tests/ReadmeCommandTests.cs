using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NerfDatasetCreator.Tests;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// The README's headless commands run as written, with the installed <c>nerf-dataset</c> command: every line of a
    /// README code block that starts with <c>nerf-dataset </c> and has no placeholder (<c>&lt;…&gt;</c>, <c>[…]</c>,
    /// <c>a|b</c>) runs, in order, in a folder laid out like the repository root (the sample's configs under
    /// Assets/Samples/NeRFSample/) with a nerf_synthetic-style <c>nerf_synthetic/lego</c> beside it (the real lego cameras, analytic RGBA images that
    /// <c>check</c> can pass), and exits 0.
    /// </summary>
    [TestFixture]
    public class ReadmeCommandTests
    {
        static string Readme => File.ReadAllText(Path.Combine(InstalledTool.RepositoryRoot, "README.md"));

        /// <summary>The lines of the README's fenced code blocks.</summary>
        static IEnumerable<string> CodeLines(string markdown)
        {
            var inside = false;
            foreach (var raw in markdown.Split('\n'))
            {
                var line = raw.TrimEnd('\r');
                if (line.TrimStart().StartsWith("```", StringComparison.Ordinal)) { inside = !inside; continue; }
                if (inside) yield return line.Trim();
            }
        }

        static bool HasPlaceholder(string line) => Regex.IsMatch(line, @"[<>\[\]|…]");

        public static List<string> RunnableToolLines(string markdown) =>
            CodeLines(markdown).Where(l => l.StartsWith("nerf-dataset ", StringComparison.Ordinal) && !HasPlaceholder(l)).ToList();

        [Test]
        public void TheReadmeShowsPlanValidateAndConvertAsRunnableLines()
        {
            var commands = RunnableToolLines(Readme).Select(l => l.Split(' ')[1]).ToList();
            Assert.That(commands, Is.SupersetOf(new[] { "plan", "validate", "convert" }));
            Assert.That(RunnableToolLines(Readme), Has.Some.Contains("--config Assets/Samples/NeRFSample/"), "plan uses a sample config that exists");
        }

        [Test]
        public void TheReadmeInstallsTheToolThePackedWay()
        {
            // InstalledTool runs exactly these two steps (with temporary folders): keep the README's in step.
            var lines = CodeLines(Readme).ToList();
            Assert.That(lines, Has.Some.Match(@"^dotnet pack Assets/NeRFDatasetCreator/Tools~/nerf-dataset -o \S+$"));
            Assert.That(lines, Has.Some.Match(@"^dotnet tool install --global --add-source \S+ NerfDatasetCreator\.Tool$"));
        }

        [Test]
        public void EveryRunnableReadmeLineExits0AsWritten()
        {
            using var scratch = new Scratch();
            var samples = scratch.PathOf("Assets", "Samples", "NeRFSample");
            Directory.CreateDirectory(samples);
            foreach (var config in Directory.GetFiles(Path.Combine(InstalledTool.RepositoryRoot, "Assets", "Samples", "NeRFSample"), "*.json"))
                File.Copy(config, Path.Combine(samples, Path.GetFileName(config)));
            AnalyticLego.Write(scratch.PathOf("nerf_synthetic", "lego"), 64, "train", "val", "test");

            var lines = RunnableToolLines(Readme);
            Assert.That(lines, Is.Not.Empty);
            foreach (var line in lines)
            {
                // Plain words only (checked above: no quotes, no placeholders), so a split on spaces is the shell's.
                Assert.That(line, Does.Not.Contain("\"").And.Not.Contain("'"));
                var arguments = line.Substring("nerf-dataset ".Length);
                var run = InstalledTool.Run(InstalledTool.Path, arguments, scratch.Root);
                TestContext.Progress.WriteLine("{0}  -> exit {1}, {2:0.00} s", line, run.ExitCode, run.Seconds);
                Assert.That(run.ExitCode, Is.EqualTo(0), line + "\n" + run);
                Assert.That(run.Err, Does.Not.Contain("error:"), line);
            }
            Assert.That(File.Exists(scratch.PathOf("datasets", "nerf-sample", "transforms_train.json")), Is.True, "plan wrote the sample's cameras");
        }
    }
}
