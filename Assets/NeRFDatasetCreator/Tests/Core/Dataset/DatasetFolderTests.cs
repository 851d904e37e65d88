using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetFolderTests
    {
        [Test]
        public void ReadsNerfSyntheticLego()
        {
            var doc = DatasetFolder.ReadFile(Fixtures.LegoTrainPath, DatasetReadMode.Strict);
            Assert.That(doc.Problems, Is.Empty);
            Assert.That(doc.CameraAngleX, Is.EqualTo(0.6911112070083618));
            Assert.That(doc.Frames, Has.Count.EqualTo(100));
            var first = doc.Frames[0];
            Assert.That(first.FilePath, Is.EqualTo("./train/r_0"));
            Assert.That(first.Rotation, Is.EqualTo(0.012566370614359171));
            Assert.That(first.TransformMatrix.Value[0, 0], Is.EqualTo(-0.9999021887779236));
            Assert.That(first.TransformMatrix.Value[1, 3], Is.EqualTo(3.845470428466797));
            Assert.That(first.TransformMatrix.Value[3, 3], Is.EqualTo(1.0));
            Assert.That(first.Problems, Is.Empty);
        }

        [Test]
        public void LegoPosesAreRigidAndAboutFourFromTheOrigin()
        {
            foreach (var frame in DatasetFolder.ReadFile(Fixtures.LegoTrainPath, DatasetReadMode.Strict).Frames)
            {
                var m = frame.TransformMatrix.Value;
                Assert.That(m.Determinant3x3, Is.EqualTo(1.0).Within(1e-5));
                Assert.That(m.Translation.Length, Is.EqualTo(4.031).Within(0.01));
            }
        }

        [Test]
        public void StructuralMistakesAreListedNotThrown()
        {
            var doc = DatasetFolder.Read("{ \"frames\": [ { \"file_path\": 3, \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1],[0,0,0,1]] }, 7 ] }");
            Assert.That(doc.Problems, Is.EqualTo(new[] { "camera_angle_x is missing." }));
            Assert.That(doc.Frames[0].Problems, Is.EqualTo(new[] { "file_path is not a string.", "transform_matrix row 2 is not a list of 4 numbers." }));
            Assert.That(doc.Frames[1].Problems, Is.EqualTo(new[] { "is not an object." }));
        }

        [Test]
        public void NaNTokensAreReadAsNumbers()
        {
            // Python's json.dump writes NaN for float('nan'); the validator must see the value to report it.
            var doc = DatasetFolder.Read("{ \"camera_angle_x\": 0.5, \"frames\": [ { \"file_path\": \"./train/r_0\", \"transform_matrix\": [[NaN,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]] } ] }");
            Assert.That(double.IsNaN(doc.Frames[0].TransformMatrix.Value[0, 0]), Is.True);
        }

        [Test]
        public void MalformedJsonGivesLineAndColumn()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetFolder.Read("{\n  \"camera_angle_x\": 0.5,\n  \"frames\": [\n}", "transforms_train.json"));
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Message, Does.StartWith("transforms_train.json(4,"));
        }

        [Test]
        public void AnEmptyTransformsFileSaysWhatItShouldHold()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetFolder.Read("", "transforms_val.json"));
            Assert.That(e.Message, Does.StartWith("transforms_val.json: the file is empty. A transforms file is a JSON object with camera_angle_x and frames"));
        }

        [Test]
        public void TextAfterTheObjectIsMalformed()
        {
            // The original plugin appended a second object on every run.
            Assert.Throws<SettingsFormatException>(() => DatasetFolder.Read("{ \"camera_angle_x\": 0.5, \"frames\": [] }{ \"camera_angle_x\": 0.5, \"frames\": [] }"));
        }

        /// <summary>Writes <c>transforms_train.json</c> with one frame holding <paramref name="frameKeys"/> (JSON members) into <paramref name="root"/>.</summary>
        static void WriteTrain(string root, string frameKeys)
        {
            Directory.CreateDirectory(root);
            File.WriteAllText(Path.Combine(root, "transforms_train.json"), "{ \"camera_angle_x\": 0.5, \"frames\": [ { \"file_path\": \"./train/r_0\", " +
                "\"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]" + frameKeys + " } ] }");
        }

        static void Touch(string path)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            File.WriteAllBytes(path, new byte[] { 1 });
        }

        [Test]
        public void EveryFileIsResolvedFromItsKeyInsideTheDataset()
        {
            using (var temp = new TempFolder())
            {
                var root = temp.Combine("data");
                var keys = new[] { "depth_path", "normal_path", "mask_path", "instance_path", "semantic_path", "clean_path", "sharp_path" };
                WriteTrain(root, string.Concat(keys.Select(k => ", \"" + k + "\": \"./train/r_0_" + k.Replace("_path", "") + ".png\"")));
                Touch(Path.Combine(root, "train", "r_0.png"));
                foreach (var k in keys) Touch(Path.Combine(root, "train", "r_0_" + k.Replace("_path", "") + ".png"));
                var frame = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Strict).Frames.Single();
                Assert.That(frame.Image.Relative, Is.EqualTo("train/r_0.png"), "file_path + \".png\", as the loaders read it");
                Assert.That(frame.Image.FullPath, Is.EqualTo(Path.Combine(Path.GetFullPath(root), "train", "r_0.png")));
                Assert.That(frame.FileKeys.Select(p => p.Key), Is.EqualTo(keys), "every *_path key, in the file's order");
                foreach (var k in keys)
                    Assert.That(frame.Existing(k), Is.EqualTo("train/r_0_" + k.Replace("_path", "") + ".png"), k);
                Assert.That(frame.FileProblems, Is.Empty);
            }
        }

        [Test]
        public void AFileNoKeyNamesIsNeverGuessedFromTheImagesName()
        {
            using (var temp = new TempFolder())
            {
                var root = temp.Combine("data");
                WriteTrain(root, "");
                Touch(Path.Combine(root, "train", "r_0.png"));
                // nerf_synthetic's own companions: 8-bit pictures that only look like this plugin's depth and normals.
                Touch(Path.Combine(root, "train", "r_0_depth_0000.png"));
                Touch(Path.Combine(root, "train", "r_0_normal_0000.png"));
                var frame = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Strict).Frames.Single();
                Assert.That(frame.Image.Exists, Is.True);
                Assert.That(frame.Existing("depth_path"), Is.Null);
                Assert.That(frame.Existing("normal_path"), Is.Null);
                Assert.That(frame.Named("depth_path"), Is.Null, "no key, no file");
            }
        }

        [Test]
        public void APathOutsideTheDatasetIsRefusedNamingTheKeyAndTheFile()
        {
            using (var temp = new TempFolder())
            {
                var root = temp.Combine("data");
                WriteTrain(root, ", \"depth_path\": \"../secret.png\", \"mask_path\": \"./train/r_0_mask.png\"");
                Touch(Path.Combine(root, "train", "r_0.png"));
                Touch(temp.Combine("secret.png")); // exists, but outside: never read
                var strict = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Strict).Frames.Single();
                Assert.That(strict.Named("depth_path").IsInside, Is.False);
                Assert.That(strict.Named("depth_path").FullPath, Is.Null);
                Assert.That(strict.Existing("depth_path"), Is.Null);
                Assert.That(strict.FileProblems, Has.Count.EqualTo(2));
                Assert.That(strict.FileProblems[0], Does.StartWith("depth_path ../secret.png leaves the dataset folder (leaves " + root));
                Assert.That(strict.FileProblems[1], Is.EqualTo("mask_path ./train/r_0_mask.png is missing."));

                var lenient = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Lenient).Frames.Single();
                Assert.That(lenient.Named("depth_path").IsInside, Is.False, "lenient reads never leave the dataset either");
                Assert.That(lenient.Existing("depth_path"), Is.Null);
                Assert.That(lenient.FileProblems, Is.Empty, "lenient mode lists nothing");
            }
        }

        [Test]
        public void LenientModeReadsNerfSyntheticLegoWithoutProblems()
        {
            var root = Path.GetDirectoryName(Fixtures.LegoTrainPath);
            var lenient = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Lenient);
            Assert.That(lenient.Problems, Is.Empty);
            Assert.That(lenient.Split, Is.EqualTo("train"));
            Assert.That(lenient.CameraAngleX, Is.EqualTo(0.6911112070083618));
            Assert.That(lenient.Frames, Has.Count.EqualTo(100));
            Assert.That(lenient.Lens, Is.Null, "a pinhole");
            var first = lenient.Frames[0];
            Assert.That(first.Problems, Is.Empty);
            Assert.That(first.FileKeys, Is.Empty, "nerf_synthetic names no pass files");
            Assert.That(first.Image.Relative, Is.EqualTo("train/r_0.png"));
            Assert.That(first.Image.Exists, Is.False, "the fixture holds the transforms file only");
            Assert.That(first.FileProblems, Is.Empty);
            Assert.That(first.Time.Any, Is.False);
            Assert.That(first.Shutter.HasStart, Is.False);
            Assert.That(first.Exposure.Recorded, Is.False);
            Assert.That(first.TransformMatrix.Value[1, 3], Is.EqualTo(3.845470428466797));
            // Strict mode lists what lenient mode leaves to the caller: here the missing images, by key and file.
            var strict = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Strict);
            Assert.That(strict.Problems, Is.Empty);
            Assert.That(strict.Frames[0].FileProblems, Is.EqualTo(new[] { "file_path ./train/r_0 is missing." }));
            // Another tool's file without camera_angle_x: lenient reads it, strict says so.
            Assert.That(DatasetFolder.Read("{ \"frames\": [] }", "transforms.json", DatasetReadMode.Lenient).Problems, Is.Empty);
            Assert.That(DatasetFolder.Read("{ \"frames\": [] }", "transforms.json", DatasetReadMode.Strict).Problems, Is.EqualTo(new[] { "camera_angle_x is missing." }));
        }

        [Test]
        public void EachFeaturesKeysReadBackAsTheWritersWroteThem()
        {
            var s = new DatasetSettings { Seed = 11 };
            s.Train.Count = 5;
            s.Time.Mode = TimeMode.Monocular;
            s.Time.StartSeconds = 0.5;
            s.Time.EndSeconds = 1.5;
            s.MotionBlur.Enabled = true;
            s.MotionBlur.Shutter = 0.5;
            s.Exposure.Mode = ExposureMode.Random;
            s.Exposure.EvMin = -1;
            s.Exposure.EvMax = 1;
            s.Exposure.GainMin = 0.8;
            s.Exposure.GainMax = 1.25;
            s.Lens.Model = LensSettings.ModelNames.OpenCv;
            s.Lens.K1 = -0.1;
            s.Lens.K2 = 0.02;
            s.Lens.P1 = 0.001;
            s.Lens.P2 = -0.002;
            var plan = CapturePlan.Build(s, PlanTarget.Headless);
            var views = plan.Views.Where(v => v.Split == DatasetSplit.Train).OrderBy(v => v.Index).ToList();
            var exposure = ExposurePlan.Of(s);
            var read = DatasetFolder.Read(BlenderTransformsWriter.Write(plan, DatasetSplit.Train), "transforms_train.json", DatasetReadMode.Strict);
            Assert.That(read.Problems, Is.Empty);
            Assert.That(read.LensProblems, Is.Empty);
            Assert.That(TransformsLens.Same(read.Lens, s.Lens.ToDistortion()), Is.True, "lens keys (TransformsLensKeys)");
            Assert.That(read.Frames, Has.Count.EqualTo(views.Count));
            for (var i = 0; i < views.Count; i++)
            {
                var frame = read.Frames[i];
                var view = views[i];
                Assert.That(frame.Problems, Is.Empty);
                Assert.That(frame.TransformMatrix, Is.EqualTo(view.TransformMatrix), "transform_matrix as written");
                Assert.That(frame.Time.Time, Is.EqualTo(view.Time.Value.Normalised), "time");
                Assert.That(frame.Time.Seconds, Is.EqualTo(view.Time.Value.Seconds), "time_seconds");
                // A monocular capture writes no time_step / camera_id (TransformsFramesText writes them for multi-view only).
                Assert.That(view.Time.Value.Camera, Is.LessThan(0));
                Assert.That(frame.Time.Step, Is.Null, "time_step");
                Assert.That(frame.Time.Camera, Is.Null, "camera_id");
                Assert.That(frame.Shutter.Start, Is.EqualTo(view.Motion.StartMatrix), "transform_matrix_start");
                Assert.That(frame.Shutter.End, Is.EqualTo(view.Motion.EndMatrix), "transform_matrix_end");
                var e = exposure.For(DatasetSplit.Train, view.Index);
                Assert.That(frame.Exposure.Problem, Is.Null);
                Assert.That(frame.Exposure.Values.Value.Ev, Is.EqualTo(e.Ev), "exposure_ev");
                Assert.That(new[] { frame.Exposure.Values.Value.R, frame.Exposure.Values.Value.G, frame.Exposure.Values.Value.B }, Is.EqualTo(new[] { e.R, e.G, e.B }), "white_balance");
            }
        }

        static IEnumerable<TestCaseData> Texts()
        {
            var lego = Fixtures.Text("nerf_synthetic_lego", "transforms_train.json");
            yield return new TestCaseData(lego).SetName("Streamed_Lego");
            yield return new TestCaseData(lego.Substring(0, lego.Length / 2)).SetName("Streamed_TruncatedLego");
            yield return new TestCaseData("{ \"frames\": [ { \"file_path\": 3, \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1],[0,0,0,1]] }, 7 ], \"w\": 1.5 }").SetName("Streamed_StructuralMistakes");
            yield return new TestCaseData("{ \"camera_angle_x\": 0.5, \"frames\": [ { \"file_path\": \"./train/r_0\", \"depth_path\": 4, \"transform_matrix\": [[NaN,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]] } ] }").SetName("Streamed_NaN");
            yield return new TestCaseData("{\n  \"camera_angle_x\": 0.5,\n  \"frames\": [\n}").SetName("Streamed_Malformed");
            yield return new TestCaseData("{ \"camera_angle_x\": 0.5, \"frames\": [] }{ \"frames\": [] }").SetName("Streamed_TextAfter");
            yield return new TestCaseData("{ \"frames\": [[ {} ] }").SetName("Streamed_NestedListUnclosed");
            yield return new TestCaseData("{ \"frames\": 3, \"camera_angle_x\": \"wide\" }").SetName("Streamed_FramesNotAList");
            yield return new TestCaseData("{ }").SetName("Streamed_Empty");
            yield return new TestCaseData("[1, 2]").SetName("Streamed_NotAnObject");
            yield return new TestCaseData("").SetName("Streamed_NoText");
        }

        /// <summary>The streaming reader (validate's, for 87 MB files) sees exactly what the whole-text reader sees, and fails alike.</summary>
        [TestCaseSource(nameof(Texts))]
        public void StreamingReadsWhatTheWholeTextReaderReads(string text)
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("transforms_train.json");
                File.WriteAllText(path, text);
                DatasetSplitFile whole = null, streamed = null;
                SettingsFormatException wholeError = null, streamedError = null;
                var frames = new List<DatasetFrame>();
                IOException wholeRefused = null, streamedRefused = null;
                try { whole = DatasetFolder.ReadSplit(temp.Path, "train", DatasetReadMode.Strict); } catch (SettingsFormatException e) { wholeError = e; } catch (IOException e) { wholeRefused = e; }
                try { streamed = DatasetFolder.ReadSplit(temp.Path, "train", DatasetReadMode.Strict, f => frames.Add(f)); } catch (SettingsFormatException e) { streamedError = e; } catch (IOException e) { streamedRefused = e; }
                if (wholeRefused != null)
                {
                    // 0 bytes: refused unread by both (ReadableFile: an empty file, or a pipe or device, is never opened).
                    Assert.That(text, Is.Empty);
                    Assert.That(streamedRefused?.Message, Is.EqualTo(wholeRefused.Message));
                    return;
                }
                if (wholeError != null)
                {
                    Assert.That(streamedError, Is.Not.Null, "both refuse it");
                    Assert.That(streamedError.Line, Is.EqualTo(wholeError.Line));
                    return;
                }
                Assert.That(streamedError, Is.Null);
                Assert.That(streamed.Problems, Is.EqualTo(whole.Problems));
                Assert.That(streamed.CameraAngleX, Is.EqualTo(whole.CameraAngleX));
                Assert.That(streamed.W, Is.EqualTo(whole.W));
                Assert.That(streamed.FrameCount, Is.EqualTo(whole.Frames.Count));
                if (streamed.Frames.Count == 0) // the streaming reader keeps none, unless it fell back to the whole text
                    Assert.That(frames.Count, Is.EqualTo(whole.Frames.Count));
                for (var i = 0; i < frames.Count; i++)
                {
                    Assert.That(frames[i].Index, Is.EqualTo(i));
                    Assert.That(frames[i].FilePath, Is.EqualTo(whole.Frames[i].FilePath));
                    Assert.That(frames[i].Rotation, Is.EqualTo(whole.Frames[i].Rotation));
                    Assert.That(frames[i].Problems, Is.EqualTo(whole.Frames[i].Problems));
                    Assert.That(frames[i].FileKeys, Is.EqualTo(whole.Frames[i].FileKeys));
                    Assert.That(frames[i].TransformMatrix.HasValue, Is.EqualTo(whole.Frames[i].TransformMatrix.HasValue));
                    if (frames[i].TransformMatrix.HasValue)
                        for (var r = 0; r < 4; r++)
                            for (var c = 0; c < 4; c++)
                                Assert.That(frames[i].TransformMatrix.Value[r, c], Is.EqualTo(whole.Frames[i].TransformMatrix.Value[r, c]));
                }
            }
        }
    }
}
