using System;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SplatSourceTargetTests
    {
        string _root;

        [SetUp]
        public void SetUp()
        {
            _root = Path.Combine(Path.GetTempPath(), "splat-source-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(_root, true);

        [Test]
        public void TheTargetIsTheSettingsTargetPath()
        {
            File.WriteAllText(Path.Combine(_root, "dataset_config.json"), "{ \"settings\": { \"target\": \"Props/Lego\" } }");
            Assert.That(SplatSourceTarget.HierarchyPathIn(_root), Is.EqualTo("Props/Lego"));
        }

        [TestCase("{ \"settings\": { \"target\": \"\" } }")]
        [TestCase("{ \"settings\": { \"target\": 3 } }")]
        [TestCase("{ \"settings\": {} }")]
        [TestCase("not json")]
        public void NoTargetGivesNull(string config)
        {
            File.WriteAllText(Path.Combine(_root, "dataset_config.json"), config);
            Assert.That(SplatSourceTarget.HierarchyPathIn(_root), Is.Null);
        }

        [Test]
        public void NoConfigGivesNull()
        {
            Assert.That(SplatSourceTarget.HierarchyPathIn(_root), Is.Null);
            Assert.That(SplatSourceTarget.HierarchyPathIn(null), Is.Null);
        }
    }
}
