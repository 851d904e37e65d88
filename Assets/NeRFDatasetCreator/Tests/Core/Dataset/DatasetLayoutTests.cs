using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetLayoutTests
    {
        [TestCase(DatasetSplit.Train, 0, DatasetFileKind.Color, "train/r_0.png")]
        [TestCase(DatasetSplit.Val, 12, DatasetFileKind.Color, "val/r_12.png")]
        [TestCase(DatasetSplit.Test, 7, DatasetFileKind.DepthPng, "test/r_7_depth_0000.png")]
        [TestCase(DatasetSplit.Test, 7, DatasetFileKind.DepthExr, "test/r_7_depth_0000.exr")]
        [TestCase(DatasetSplit.Test, 7, DatasetFileKind.NormalPng, "test/r_7_normal_0000.png")]
        [TestCase(DatasetSplit.Test, 7, DatasetFileKind.NormalExr, "test/r_7_normal_0000.exr")]
        [TestCase(DatasetSplit.Train, 7, DatasetFileKind.MaskPng, "train/r_7_mask_0000.png")]
        [TestCase(DatasetSplit.Train, 100000, DatasetFileKind.Color, "train/r_100000.png")]
        public void FileNamesFollowNerfSynthetic(DatasetSplit split, int index, DatasetFileKind kind, string expected)
        {
            Assert.That(DatasetLayout.RelativePath(split, index, kind), Is.EqualTo(expected));
            Assert.That(DatasetLayout.FrameKeyPath(split, index, kind), Is.EqualTo("./" + expected));
        }

        [TestCase(DatasetSplit.Train, 0, "./train/r_0")]
        [TestCase(DatasetSplit.Test, 199, "./test/r_199")]
        public void FramePathHasNoExtension(DatasetSplit split, int index, string expected)
        {
            Assert.That(DatasetLayout.FramePath(split, index), Is.EqualTo(expected));
        }

        [TestCase(DatasetSplit.Train, "transforms_train.json")]
        [TestCase(DatasetSplit.Val, "transforms_val.json")]
        [TestCase(DatasetSplit.Test, "transforms_test.json")]
        public void TransformsFileNames(DatasetSplit split, string expected)
        {
            Assert.That(DatasetLayout.TransformsFileName(split), Is.EqualTo(expected));
        }

        [Test]
        public void SplitNamesAreLowercaseAndParseBack()
        {
            foreach (var split in DatasetSplits.All)
            {
                var name = DatasetSplits.Name(split);
                Assert.That(name, Is.EqualTo(name.ToLowerInvariant()));
                Assert.That(DatasetSplits.TryParse(name, out var parsed), Is.True);
                Assert.That(parsed, Is.EqualTo(split));
            }
            Assert.That(DatasetSplits.TryParse("Train", out _), Is.False, "one spelling only");
        }

        [Test]
        public void FileKindsFollowTheSplitsOutputs()
        {
            var split = new SplitSettings { Depth = ExtraOutput.Exr, Normal = ExtraOutput.None, Mask = true };
            Assert.That(DatasetLayout.FileKinds(split), Is.EqualTo(new[] { DatasetFileKind.Color, DatasetFileKind.DepthExr, DatasetFileKind.MaskPng }));
        }
    }
}
