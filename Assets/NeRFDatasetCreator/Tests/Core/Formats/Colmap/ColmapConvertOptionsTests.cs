using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary><c>convert --to colmap --binary --points N --min-track N</c> on the command line.</summary>
    public class ColmapConvertOptionsTests
    {
        [Test]
        public void TheModelOptionsAreParsed()
        {
            var run = ToolCommandLine.Parse(new[] { "convert", "ds", "--to", "colmap", "--binary", "--points", "5000", "--min-track", "3" });
            Assert.That(run.Errors, Is.Empty);
            var options = ((ConvertCommand.Options)run.Options).ColmapModelOptions;
            Assert.That((options.Binary, options.MaxPoints, options.MinTrackLength), Is.EqualTo((true, (int?)5000, 3)));
        }

        [Test]
        public void WithoutThemTheDefaultsApply()
        {
            var run = ToolCommandLine.Parse(new[] { "convert", "ds", "--to", "colmap" });
            Assert.That(run.Errors, Is.Empty);
            Assert.That(((ConvertCommand.Options)run.Options).ColmapModelOptions, Is.Null);
            Assert.That(ColmapOptions.Default.MinTrackLength, Is.EqualTo(2));
            Assert.That(ColmapOptions.Default.Binary, Is.False);
        }

        [TestCase("--points", "0")]
        [TestCase("--points", "many")]
        [TestCase("--min-track", "-1")]
        public void ABadValueIsAUsageError(string option, string value)
        {
            var run = ToolCommandLine.Parse(new[] { "convert", "ds", "--to", "colmap", option, value });
            Assert.That(run.Errors, Has.Exactly(1).StartWith(option + " " + value + ": "));
        }

        [Test]
        public void TheyBelongToColmap()
        {
            var run = ToolCommandLine.Parse(new[] { "convert", "ds", "--to", "nerfstudio", "--binary" });
            Assert.That(run.Errors, Has.Some.Contains("--to colmap"));
        }
    }
}
