using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// validate's check for two frames naming one image, on plan-only datasets (no images to check): a frame at its
    /// own place (frame i of transforms_train.json naming ./train/r_i) is remembered as a bit, any other path whole
    /// (FramePathRegistry), and either may come first. The expected lines follow the message's documented form.
    /// </summary>
    [TestFixture]
    public class DuplicateFramePathTests
    {
        TempFolder _temp;

        [SetUp]
        public void SetUp() => _temp = new TempFolder();

        [TearDown]
        public void TearDown() => _temp.Dispose();

        const string Identity = "[[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]";
        const string Twice = "; two frames of one image train on it twice and exports write it twice (give every frame its own image).";

        string Dataset(string[] train, string[] val, string[] test, string trainTail = "]}")
        {
            var folder = _temp.Combine("d" + Directory.GetDirectories(_temp.Path).Length);
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "dataset_config.json"), "{ \"imagesRendered\": false }");
            void Write(string split, string[] paths, string tail) => File.WriteAllText(Path.Combine(folder, "transforms_" + split + ".json"),
                "{\"camera_angle_x\": 0.69, \"frames\": [" + string.Join(",", paths.Select(p => "{\"file_path\": \"" + p + "\", \"transform_matrix\": " + Identity + "}")) + tail);
            Write("train", train, trainTail);
            Write("val", val, "]}");
            Write("test", test, "]}");
            return folder;
        }

        static string[] Duplicates(string folder) =>
            DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()).Where(p => p.Contains("file_path is also")).ToArray();

        static string[] Own(string split, int count) => Enumerable.Range(0, count).Select(i => "./" + split + "/r_" + i).ToArray();

        [Test]
        public void OwnPlacesAreNoDuplicates()
        {
            Assert.That(Duplicates(Dataset(Own("train", 200), Own("val", 70), Own("test", 65))), Is.Empty);
        }

        [Test]
        public void ALaterFrameNamingAnOwnPlaceIsTheDuplicate()
        {
            var train = Own("train", 10);
            train[7] = "./train/r_3";
            Assert.That(Duplicates(Dataset(train, Own("val", 2), Own("test", 2))), Is.EqualTo(new[]
            {
                "transforms_train.json frame 7 (./train/r_3): file_path is also transforms_train.json frame 3's" + Twice,
            }));
        }

        [Test]
        public void AnOwnPlaceAfterAnotherFrameNamedItIsTheDuplicate()
        {
            var train = Own("train", 10);
            train[2] = "./train/r_9";
            Assert.That(Duplicates(Dataset(train, Own("val", 2), Own("test", 2))), Is.EqualTo(new[]
            {
                "transforms_train.json frame 9 (./train/r_9): file_path is also transforms_train.json frame 2's" + Twice,
            }));
        }

        [Test]
        public void PathsCompareIgnoringCaseAcrossFiles()
        {
            var val = Own("val", 6);
            val[4] = "./TRAIN/R_4";
            var test = Own("test", 3);
            test[1] = "./val/r_4x"; // not a view's path: kept whole
            var test2 = test.Concat(new[] { "./VAL/R_4X" }).ToArray();
            Assert.That(Duplicates(Dataset(Own("train", 5), val, test2)), Is.EqualTo(new[]
            {
                "transforms_val.json frame 4 (./TRAIN/R_4): file_path is also transforms_train.json frame 4's" + Twice,
                "transforms_test.json frame 3 (./VAL/R_4X): file_path is also transforms_test.json frame 1's" + Twice,
            }));
        }

        [Test]
        public void LeadingZerosNameAnotherFile()
        {
            var train = Own("train", 5);
            train[4] = "./train/r_03";
            var val = Own("val", 3);
            val[0] = "train/r_03"; // the same as ./train/r_03
            Assert.That(Duplicates(Dataset(train, val, Own("test", 1))), Is.EqualTo(new[]
            {
                "transforms_val.json frame 0 (train/r_03): file_path is also transforms_train.json frame 4's" + Twice,
            }));
        }

        [Test]
        public void AMalformedFileAddsNoPaths()
        {
            // The train file breaks after its frames: its parse error stands alone, and val's frame naming train's r_0 is no duplicate.
            var val = Own("val", 2);
            val[1] = "./train/r_0";
            var folder = Dataset(Own("train", 3), val, Own("test", 1), trainTail: "], \"w\": }");
            var problems = DatasetValidator.Validate(folder).Problems.Select(p => p.ToString()).ToArray();
            Assert.That(problems.Where(p => p.StartsWith("transforms_train.json")).Count(), Is.EqualTo(1));
            Assert.That(problems.Where(p => p.Contains("file_path is also")), Is.Empty);
        }
    }
}
