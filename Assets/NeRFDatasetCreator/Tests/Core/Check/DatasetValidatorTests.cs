using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetValidatorTests
    {
        TempFolder _temp;
        string _lego;

        [SetUp]
        public void SetUp()
        {
            _temp = new TempFolder();
            _lego = _temp.Combine("lego");
            TestDatasets.Lego(_lego);
        }

        [TearDown]
        public void TearDown() => _temp.Dispose();

        string[] Lines(string folder) => DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()).ToArray();

        void Edit(string file, string from, string to)
        {
            var path = Path.Combine(_lego, file);
            var text = File.ReadAllText(path);
            Assert.That(text, Does.Contain(from), "the fixture edit must apply");
            File.WriteAllText(path, ReplaceFirst(text, from, to));
        }

        static string ReplaceFirst(string text, string from, string to)
        {
            var at = text.IndexOf(from, System.StringComparison.Ordinal);
            return text.Substring(0, at) + to + text.Substring(at + from.Length);
        }

        [Test]
        public void RealLegoTransformsWithImagesOfTheDeclaredSizeAreValid()
        {
            var report = DatasetValidator.Validate(_lego);
            Assert.That(report.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(report.Warnings, Is.Empty);
            Assert.That(report.IsValid, Is.True);
            Assert.That(report.ImagesChecked, Is.EqualTo(300));
            Assert.That(report.ImageWidth, Is.EqualTo(800));
            Assert.That(report.Summary(), Does.Contain("train 100, val 100, test 100 frames; 300 images (800×800)"));
        }

        [Test]
        public void ACameraInsideNerfsNearDistanceIsAWarningNotAProblem()
        {
            // Train r_0 sits at (−0.054, 3.845, 1.208), 4.03 from the origin; moved to (−0.054, 1, 1) it is 1.42 away,
            // nearer than bmild/nerf's fixed near plane 2.
            Edit("transforms_train.json", "3.845470428466797", "1.0");
            Edit("transforms_train.json", "1.2080823183059692", "1.0");
            var report = DatasetValidator.Validate(_lego);
            Assert.That(report.Problems, Is.Empty);
            Assert.That(report.Warnings.Select(w => w.ToString()), Has.Exactly(1).Contains("transform_matrix = 1.415").And.Contains("closer to the target's surface than NeRF's fixed near distance 2").And.Contains("1 of 300 cameras"));
        }

        [Test]
        public void MissingImage()
        {
            File.Delete(Path.Combine(_lego, "train", "r_5.png"));
            Assert.That(Lines(_lego), Is.EqualTo(new[] { "transforms_train.json frame 5 (./train/r_5): image ./train/r_5.png is missing." }));
        }

        [Test]
        public void NaNInAMatrix()
        {
            Edit("transforms_val.json", "-0.9999021887779236", "NaN");
            Assert.That(Lines(_lego), Is.EqualTo(new[] { "transforms_val.json frame 0 (./val/r_0): transform_matrix has a NaN or infinite entry." }));
        }

        [Test]
        public void ShearedMatrix()
        {
            // Frame 0's first row starts -0.9999021887779236, 0.004192245192825794: shear x by 0.1·y.
            Edit("transforms_test.json", "0.004192245192825794", "0.104192245192825794");
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.StartWith("transforms_test.json frame 0 (./test/r_0): transform_matrix's rotation is not orthonormal"));
        }

        [Test]
        public void MirroredMatrix()
        {
            // Negating frame 0's first column keeps it orthonormal but makes det = −1, as Unity's own matrix
            // (left-handed) would be without the Y/Z swap.
            Edit("transforms_train.json", "-0.9999021887779236", "0.9999021887779236");
            Edit("transforms_train.json", "-0.013988681137561798", "0.013988681137561798");
            Edit("transforms_train.json", "-4.656612873077393e-10", "4.656612873077393e-10");
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.StartWith("transforms_train.json frame 0 (./train/r_0): transform_matrix's rotation has determinant -"));
            Assert.That(lines[0], Does.Contain("mirrored"));
        }

        [Test]
        public void MixedSizes()
        {
            TestPng.Write(Path.Combine(_lego, "test", "r_2.png"), 400, 400);
            Assert.That(Lines(_lego), Is.EqualTo(new[]
            {
                "transforms_test.json frame 2 (./test/r_2): image ./test/r_2.png is 400×400 but ./train/r_0.png is 800×800; loaders stack all images and need one size.",
            }));
        }

        [Test]
        public void MixedChannels()
        {
            TestPng.Write(Path.Combine(_lego, "val", "r_3.png"), 800, 800, 8, PngInfo.ColorTypeRgb);
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.Contain("frame 3").And.Contain("8-bit RGB but ./train/r_0.png is 8-bit RGBA"));
        }

        [Test]
        public void TruncatedPng()
        {
            var path = Path.Combine(_lego, "val", "r_9.png");
            var bytes = File.ReadAllBytes(path);
            File.WriteAllBytes(path, bytes.Take(bytes.Length / 2).ToArray());
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.StartWith("transforms_val.json frame 9 (./val/r_9): ./val/r_9.png is truncated"));
        }

        [Test]
        public void MissingSplitFile()
        {
            File.Delete(Path.Combine(_lego, "transforms_val.json"));
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.StartWith("transforms_val.json: is missing"));
        }

        [Test]
        public void MalformedJsonNamesLineAndColumn()
        {
            Edit("transforms_train.json", "\"frames\": [", "\"frames\": [[");
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.Match(@"^transforms_train\.json: line \d+, column \d+: not valid JSON"));
        }

        [TestCase("0.6911112070083618", "3.5")]
        [TestCase("0.6911112070083618", "0")]
        public void CameraAngleXOutsideZeroToPi(string from, string to)
        {
            Edit("transforms_train.json", from, to);
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.StartWith("transforms_train.json: camera_angle_x = " + to + " is not in (0, π)"));
        }

        [Test]
        public void CameraAngleXMustAgreeAcrossSplits()
        {
            Edit("transforms_test.json", "0.6911112070083618", "0.7");
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.Contain("differs from transforms_train.json"));
        }

        [Test]
        public void FilePathWithExtensionIsAProblem()
        {
            Edit("transforms_train.json", "\"./train/r_0\"", "\"./train/r_0.png\"");
            var lines = Lines(_lego);
            Assert.That(lines, Has.Length.EqualTo(1));
            Assert.That(lines[0], Does.Contain("frame 0").And.Contain("ends in .png"));
        }

        [Test]
        public void EveryProblemIsListed()
        {
            File.Delete(Path.Combine(_lego, "train", "r_1.png"));
            File.Delete(Path.Combine(_lego, "train", "r_2.png"));
            TestPng.Write(Path.Combine(_lego, "test", "r_99.png"), 100, 100);
            var report = DatasetValidator.Validate(_lego);
            Assert.That(report.Problems.Select(p => p.Frame), Is.EqualTo(new[] { 1, 2, 99 }));
            Assert.That(report.IsValid, Is.False);
        }

        [Test]
        public void MissingFolder()
        {
            Assert.That(DatasetValidator.Validate(_temp.Combine("nothing")).IsValid, Is.False);
        }
    }
}
