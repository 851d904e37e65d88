using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NerfDatasetCreator.Tests;
using Newtonsoft.Json;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Every command, with every kind of exception thrown below it — at its first file operation, and at each of its
    /// file operations in turn — prints clear lines (no stack trace) and exits 0, 1 or 2.
    /// </summary>
    [TestFixture]
    public class NoStackTraceTests
    {
        static readonly Func<string, string, Exception>[] Faults =
        {
            (op, path) => new IOException("No space left on device"),
            (op, path) => new UnauthorizedAccessException("Access to the path '" + path + "' is denied."),
            (op, path) => new PathTooLongException("The path is too long."),
            (op, path) => new DirectoryNotFoundException("Could not find a part of the path."),
            (op, path) => new FileNotFoundException("Could not find file.", path),
            (op, path) => new InvalidDataException("not a PNG"),
            (op, path) => new OutOfMemoryException(),
            (op, path) => new InvalidOperationException("odd state"),
            (op, path) => new NullReferenceException(),
            (op, path) => new ArgumentException("bad argument"),
            (op, path) => new FormatException("bad format"),
            (op, path) => new OverflowException("too large"),
            (op, path) => new InvalidCastException("wrong type"),
            (op, path) => new NotSupportedException("not supported"),
            (op, path) => new JsonReaderException("Unexpected character"),
            (op, path) => new KeyNotFoundException("missing key"),
            (op, path) => new IndexOutOfRangeException(),
            (op, path) => new OperationCanceledException(),
            (op, path) => new Exception("anything at all"),
        };

        static readonly string[] ClearPrefixes = { "error: ", "warning: ", "note: ", "invalid: ", "convert refused", "merge refused", "convert failed", "kept " };

        Scratch _scratch;

        [SetUp]
        public void SetUp() => _scratch = new Scratch();

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
            _scratch.Dispose();
        }

        /// <summary>Fresh inputs for one run of <paramref name="command"/>, in a new sub-folder of the scratch folder.</summary>
        string[] Arguments(string command, int run)
        {
            var root = _scratch.PathOf(command + "-" + run);
            Directory.CreateDirectory(root);
            var sub = Scratch.In(root);
            switch (command)
            {
                case "plan": return Plan(sub);
                case "validate": return new[] { "validate", RenderedDataset.Create(sub, "ds") };
                case "convert": return new[] { "convert", RenderedDataset.Create(sub, "ds"), "--to", "ngp" };
                case "merge": return new[] { "merge", "--files", "move", "--out", sub.PathOf("lego") }.Concat(ShardFolders.Create(sub.PathOf("shards"), 2, new ViewCounts(2, 1, 1))).ToArray();
                default:
                    // clean, with something to clean: a plan killed while writing.
                    Interruptions.StopAt(8, Plan(sub));
                    return new[] { "clean", root };
            }
        }

        static string[] Plan(Scratch sub) => new[]
        {
            "plan", "--config", sub.WriteText("c.json", "{ \"splits\": { \"train\": { \"count\": 2 }, \"val\": { \"count\": 1 }, \"test\": { \"count\": 1 } } }"), "--out", sub.PathOf("out"),
        };

        [TestCase("plan")]
        [TestCase("validate")]
        [TestCase("merge")]
        [TestCase("convert")]
        [TestCase("clean")]
        public void NoCommandPrintsAStackTraceForAnyExceptionBelowIt(string command)
        {
            var steps = Interruptions.Steps(out var clean, Arguments(command, 0));
            Assert.That(clean.ExitCode, Is.EqualTo(0), clean.ToString());
            Assert.That(steps, Is.GreaterThan(0));
            var run = 1;
            // Every exception type at the first operation, then every operation with the types in turn.
            var cases = Faults.Select(f => (step: 1, fault: f)).Concat(Enumerable.Range(2, steps - 1).Select(k => (step: k, fault: Faults[k % Faults.Length])));
            foreach (var (step, fault) in cases)
            {
                var result = Interruptions.FailAt(step, fault, Arguments(command, run++));
                var where = command + " with " + fault("op", "path").GetType().Name + " at step " + step + " of " + steps + "\n" + result;
                Assert.That(result.ExitCode, Is.AnyOf(0, 1, 2), where);
                Assert.That(Interruptions.HasStackTrace(result.Out + result.Err), Is.False, where);
                var lines = result.Err.Split('\n').Where(l => l.Length > 0).ToList();
                if (result.ExitCode != 0) Assert.That(lines, Is.Not.Empty, where);
                foreach (var line in lines) Assert.That(ClearPrefixes.Any(line.StartsWith), Is.True, where + "\nunclear line: " + line);
            }
        }

        [Test]
        public void AnExceptionNoCommandHandlesIsOneLineWithExitOne()
        {
            var args = Arguments("plan", 0);
            var result = Interruptions.FailAt(1, (op, path) => new NullReferenceException(), args);
            Assert.That(result.ExitCode, Is.EqualTo(1), result.ToString());
            Assert.That(result.Err.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), result.ToString());
            Assert.That(result.Err, Does.StartWith("error: plan: stopped on an unexpected NullReferenceException"));
        }
    }
}
