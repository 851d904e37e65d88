using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class HierarchyPathTests
    {
        [Test]
        public void APathJoinsNamesFromTheRootAndSplitsBack()
        {
            var path = HierarchyPath.Join(new[] { "Props", "Lego", "Bulldozer" });
            Assert.That(path, Is.EqualTo("Props/Lego/Bulldozer"));
            Assert.That(HierarchyPath.Split(path), Is.EqualTo(new[] { "Props", "Lego", "Bulldozer" }));
            Assert.That(HierarchyPath.Split("/Props/Lego"), Is.EqualTo(new[] { "Props", "Lego" }));
            Assert.That(HierarchyPath.Split(""), Is.Empty);
            Assert.That(HierarchyPath.Split("/"), Is.Empty);
        }

        [Test]
        public void ANameWithASlashIsReportedBecauseItsPathCannotFindItAgain()
        {
            Assert.That(HierarchyPath.CheckNames("target", new[] { "Props", "Lego" }), Is.Null);
            var problem = HierarchyPath.CheckNames("target", new[] { "Props", "A/B" });
            Assert.That(problem.Field, Is.EqualTo("target"));
            Assert.That(problem.Value, Is.EqualTo("\"A/B\""));
        }
    }
}
