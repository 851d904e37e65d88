using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>The target is stored as its hierarchy path and found again from it (after a restart, an undo, a config load).</summary>
    [TestFixture]
    public class SceneObjectPathTests
    {
        GameObject root;

        [SetUp]
        public void Build()
        {
            root = new GameObject("NerfPathTestRoot");
            var middle = new GameObject("Middle");
            middle.transform.parent = root.transform;
            var leaf = new GameObject("Leaf");
            leaf.transform.parent = middle.transform;
        }

        [TearDown]
        public void Remove() => Object.DestroyImmediate(root);

        [Test]
        public void AnObjectIsFoundAgainByItsPath()
        {
            var leaf = root.transform.Find("Middle/Leaf").gameObject;
            var path = SceneObjectPath.Of(leaf);
            Assert.That(path, Is.EqualTo("NerfPathTestRoot/Middle/Leaf"));
            Assert.That(SceneObjectPath.Find(path), Is.SameAs(leaf));
            Assert.That(SceneObjectPath.Find("NerfPathTestRoot"), Is.SameAs(root));
        }

        [Test]
        public void AMissingPathFindsNothing()
        {
            Assert.That(SceneObjectPath.Find("NerfPathTestRoot/Nope"), Is.Null);
            Assert.That(SceneObjectPath.Find(""), Is.Null);
            Assert.That(SceneObjectPath.Of(null), Is.EqualTo(""));
        }

        [Test]
        public void ANameWithASlashIsWarnedAbout()
        {
            var odd = new GameObject("A/B");
            odd.transform.parent = root.transform;
            Assert.That(SceneObjectPath.Check("target", odd), Is.Not.Null);
            Assert.That(SceneObjectPath.Check("target", root), Is.Null);
        }
    }
}
