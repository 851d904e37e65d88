using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ResolutionPresetsTests
    {
        [TestCase(400, 400, 0)]
        [TestCase(800, 800, 1)]
        [TestCase(1600, 1600, 2)]
        [TestCase(800, 400, 3)]
        [TestCase(512, 512, 3)]
        public void ASizeShowsItsPresetOrCustom(int width, int height, int expected)
        {
            Assert.That(ResolutionPresets.IndexOf(width, height), Is.EqualTo(expected));
        }

        [Test]
        public void TheLabelsAreThePresetsThenCustom()
        {
            Assert.That(ResolutionPresets.Labels(), Is.EqualTo(new[] { "400 × 400", "800 × 800", "1600 × 1600", "Custom" }));
            Assert.That(ResolutionPresets.CustomIndex, Is.EqualTo(3));
        }

        [Test]
        public void ChoosingAPresetSetsBothSidesAndCustomKeepsTheSize()
        {
            var settings = new DatasetSettings { Width = 640, Height = 480 };
            ResolutionPresets.Apply(ResolutionPresets.CustomIndex, settings);
            Assert.That(settings.Width, Is.EqualTo(640));
            Assert.That(settings.Height, Is.EqualTo(480));
            ResolutionPresets.Apply(2, settings);
            Assert.That(settings.Width, Is.EqualTo(1600));
            Assert.That(settings.Height, Is.EqualTo(1600));
            Assert.That(() => ResolutionPresets.Apply(4, settings), Throws.InstanceOf<System.ArgumentOutOfRangeException>());
        }

        [Test]
        public void CustomStaysShownOnceChosenEvenForAPresetSize()
        {
            Assert.That(ResolutionPresets.Shown(800, 800, customChosen: true), Is.EqualTo(ResolutionPresets.CustomIndex));
            Assert.That(ResolutionPresets.Shown(800, 800, customChosen: false), Is.EqualTo(1));
            Assert.That(ResolutionPresets.Shown(640, 480, customChosen: false), Is.EqualTo(ResolutionPresets.CustomIndex));
        }

        [Test]
        public void TheDefaultSizeIsTheMiddlePreset()
        {
            var settings = new DatasetSettings();
            Assert.That(ResolutionPresets.IndexOf(settings.Width, settings.Height), Is.EqualTo(1));
        }
    }
}
