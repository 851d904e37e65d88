using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary><c>convert --images</c>: the default by where the export goes, and which targets take link and relative.</summary>
    [TestFixture]
    public class ExportImagesTests
    {
        static readonly string Root = Path.GetFullPath(Path.Combine(Path.GetTempPath(), "datasets", "lego"));

        [Test]
        public void TheDefaultIsRelativeInsideTheDatasetAndCopyElsewhere()
        {
            Assert.That(ExportImagesModes.Resolve(null, Root, Root), Is.EqualTo(ExportImages.Relative), "nerfstudio's default: the dataset folder itself");
            Assert.That(ExportImagesModes.Resolve(null, Root, Path.Combine(Root, "ngp")), Is.EqualTo(ExportImages.Relative), "ngp's default place");
            Assert.That(ExportImagesModes.Resolve(null, Root, Path.Combine(Root, "..", "lego-ngp")), Is.EqualTo(ExportImages.Copy));
            // A sibling whose name starts with the dataset's is not inside it.
            Assert.That(ExportImagesModes.Resolve(null, Root, Root + "-nerfstudio"), Is.EqualTo(ExportImages.Copy));
            Assert.That(ExportImagesModes.Resolve(ExportImages.Link, Root, Root), Is.EqualTo(ExportImages.Link), "a choice wins");
        }

        [TestCase("copy", ExportImages.Copy)]
        [TestCase("LINK", ExportImages.Link)]
        [TestCase(" relative ", ExportImages.Relative)]
        public void ParseKnowsTheThreeModes(string value, ExportImages expected)
        {
            Assert.That(ExportImagesModes.Parse(value, out var problem), Is.EqualTo(expected));
            Assert.That(problem, Is.Null);
        }

        [Test]
        public void OnlyTheExportsWhoseJsonNamesTheDatasetsFilesTakeLinkAndRelative()
        {
            Assert.That(ExportImagesModes.NamesDatasetFiles(ExportTarget.Nerfstudio), Is.True);
            Assert.That(ExportImagesModes.NamesDatasetFiles(ExportTarget.Ngp), Is.True);
            Assert.That(ExportImagesModes.NamesDatasetFiles(ExportTarget.Colmap), Is.False, "copies its images into images/ under flat names");
            Assert.That(ExportImagesModes.NamesDatasetFiles(ExportTarget.GaussianGrouping), Is.False);
            Assert.That(ExportImagesModes.NamesDatasetFiles(ExportTarget.Dynamic3dgs), Is.False, "re-encodes its images");
        }

        [Test]
        public void ReferencesNameACopiedFileByItsDatasetPathAndAFileInsideTheExportWhereItIs()
        {
            var output = Path.Combine(Root, "..", "exports", "lego-ns");
            var copy = new ExportFileReferences(ExportImages.Copy, Root, output);
            Assert.That(copy.Reference("./train/r_0.png"), Is.EqualTo("train/r_0.png"));
            Assert.That(copy.Destinations, Is.EqualTo(new[] { Path.GetFullPath(Path.Combine(output, "train", "r_0.png")) }));
            var relative = new ExportFileReferences(ExportImages.Relative, Root, output);
            Assert.That(relative.Reference("./train/r_0.png"), Is.EqualTo("../../lego/train/r_0.png"));
            Assert.That(relative.Destinations, Is.Empty);
            var inside = new ExportFileReferences(ExportImages.Copy, Root, Path.Combine(Root, "object_3"));
            Assert.That(inside.Reference("object_3/masks/r_0.png"), Is.EqualTo("masks/r_0.png"), "--object's masks are written into the export");
            Assert.That(inside.Count, Is.EqualTo(0));
        }
    }
}
