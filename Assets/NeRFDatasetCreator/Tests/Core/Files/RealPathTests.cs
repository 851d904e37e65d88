using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <see cref="RealPath.Of"/> without links (the link cases, which need real symbolic links, are
    /// <c>Tests/Tool.Tests/DataSafetyTests</c>): ".", "..", a missing tail and the root's parent, as the OS reads them.
    /// </summary>
    [TestFixture]
    public class RealPathTests
    {
        [Test]
        public void DotsAndAMissingTailAreReadAsTheOsReadsThem()
        {
            using (var temp = new TempFolder())
            {
                var real = RealPath.Of(temp.Path, out var reason);
                Assert.That(reason, Is.Null);
                Directory.CreateDirectory(temp.Combine("a"));
                Assert.That(RealPath.Of(temp.Combine("a", ".", "..", "b", "c"), out _), Is.EqualTo(Path.Combine(real, "b", "c")), "b/c does not exist: appended as written");
                Assert.That(RealPath.Inside(temp.Combine("a", "..", "a", "x"), temp.Combine("a")), Is.True);
                Assert.That(RealPath.Inside(temp.Combine("a", "..", "ab"), temp.Combine("a")), Is.False, "a sibling whose name starts alike is not inside");
            }
        }

        [Test]
        public void TheRootsParentIsTheRoot()
        {
            var root = Path.GetPathRoot(Path.GetTempPath());
            Assert.That(RealPath.Of(root + ".." + Path.DirectorySeparatorChar + ".." + Path.DirectorySeparatorChar + "no-such-folder-32", out _),
                Is.EqualTo(root + "no-such-folder-32"));
        }
    }
}
