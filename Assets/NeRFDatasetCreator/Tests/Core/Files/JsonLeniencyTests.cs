using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class JsonLeniencyTests
    {
        [Test]
        public void CommentsAndTrailingCommasAreFoundWithLineAndColumn()
        {
            var found = JsonLeniency.Find("{\n  \"a\": 1, // note\n  \"b\": [1, 2,],\n  /* block */ \"c\": 3,\n}");
            Assert.That(found.Select(f => f.line + ":" + f.column + " " + f.what), Is.EqualTo(new[]
            {
                "2:11 a comment", "3:13 a trailing comma", "4:3 a comment", "4:21 a trailing comma",
            }));
        }

        [Test]
        public void StrictJsonAndLookalikesInsideStringsAreClean()
        {
            Assert.That(JsonLeniency.Find("{ \"url\": \"http://x/,]\", \"list\": [1, 2], \"s\": \"a \\\" // b\" }"), Is.Empty);
        }

        [Test]
        public void TheConfigReaderWarnsAboutThem()
        {
            var read = DatasetSettingsJson.Read("{ \"width\": 64, }", "c.json");
            Assert.That(read.Warnings.Single().Field, Is.EqualTo("c.json(1,14)"));
            Assert.That(read.Warnings.Single().Value, Is.EqualTo("a trailing comma"));
        }
    }
}
