using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class SparseViewsChoicesTests
    {
        [Test]
        public void TheFieldTextRoundTripsAndRefusesWhatIsNotAListOfCounts()
        {
            Assert.That(SparseViewsChoices.Text(new[] { 3, 6, 9 }), Is.EqualTo("3, 6, 9"));
            Assert.That(SparseViewsChoices.Text(new int[0]), Is.EqualTo(""));
            Assert.That(SparseViewsChoices.Parse("3, 6 9"), Is.EqualTo(new[] { 3, 6, 9 }));
            Assert.That(SparseViewsChoices.Parse("  "), Is.Empty, "empty: none");
            Assert.That(SparseViewsChoices.Parse("8x"), Is.Null);
            Assert.That(SparseViewsChoices.Parse("-3"), Is.Null);
        }
    }
}
