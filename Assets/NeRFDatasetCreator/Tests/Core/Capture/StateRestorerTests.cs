using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class StateRestorerTests
    {
        [Test]
        public void ChangesAreRestoredNewestFirst()
        {
            var log = new List<string>();
            var restorer = new StateRestorer();
            restorer.Changed("reload lock", () => log.Add("unlock"));
            restorer.Changed("async shaders", () => log.Add("async on"));
            Assert.That(restorer.RestoreAll(), Is.Empty);
            Assert.That(log, Is.EqualTo(new[] { "async on", "unlock" }));
            Assert.That(restorer.Pending, Is.Zero);
        }

        [Test]
        public void ASecondRestoreDoesNothing()
        {
            var count = 0;
            var restorer = new StateRestorer();
            restorer.Changed("flag", () => count++);
            restorer.RestoreAll();
            restorer.RestoreAll();
            Assert.That(count, Is.EqualTo(1));
        }

        [Test]
        public void ARestoreThatEndsTheRunAgainDoesNotRepeatAnyRestore()
        {
            // E.g. restoring a flag raises an editor event whose handler ends the capture a second time.
            var restorer = new StateRestorer();
            var log = new List<string>();
            restorer.Changed("first", () => log.Add("first"));
            restorer.Changed("second", () =>
            {
                log.Add("second");
                restorer.RestoreAll();
            });
            restorer.RestoreAll();
            Assert.That(log, Is.EqualTo(new[] { "second", "first" }));
        }

        [Test]
        public void AFailingRestoreIsReportedAndTheOthersStillRun()
        {
            var log = new List<string>();
            var restorer = new StateRestorer();
            restorer.Changed("reload lock", () => log.Add("unlock"));
            restorer.Changed("async shaders", () => throw new InvalidOperationException("boom"));
            var failures = restorer.RestoreAll();
            Assert.That(log, Is.EqualTo(new[] { "unlock" }));
            Assert.That(failures.Single().Message, Does.Contain("async shaders").And.Contain("boom"));
        }

        [Test]
        public void AChangeMustBeNamedAndRestorable()
        {
            var restorer = new StateRestorer();
            Assert.Throws<ArgumentException>(() => restorer.Changed("", () => { }));
            Assert.Throws<ArgumentNullException>(() => restorer.Changed("x", null));
        }
    }
}
