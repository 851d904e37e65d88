using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class TransformsReaderTests
    {
        [Test]
        public void ReadsNerfSyntheticLego()
        {
            var doc = TransformsReader.ReadFile(Fixtures.LegoTrainPath);
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
            foreach (var frame in TransformsReader.ReadFile(Fixtures.LegoTrainPath).Frames)
            {
                var m = frame.TransformMatrix.Value;
                Assert.That(m.Determinant3x3, Is.EqualTo(1.0).Within(1e-5));
                Assert.That(m.Translation.Length, Is.EqualTo(4.031).Within(0.01));
            }
        }

        [Test]
        public void StructuralMistakesAreListedNotThrown()
        {
            var doc = TransformsReader.Read("{ \"frames\": [ { \"file_path\": 3, \"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1],[0,0,0,1]] }, 7 ] }");
            Assert.That(doc.Problems, Is.EqualTo(new[] { "camera_angle_x is missing." }));
            Assert.That(doc.Frames[0].Problems, Is.EqualTo(new[] { "file_path is not a string.", "transform_matrix row 2 is not a list of 4 numbers." }));
            Assert.That(doc.Frames[1].Problems, Is.EqualTo(new[] { "is not an object." }));
        }

        [Test]
        public void NaNTokensAreReadAsNumbers()
        {
            // Python's json.dump writes NaN for float('nan'); the validator must see the value to report it.
            var doc = TransformsReader.Read("{ \"camera_angle_x\": 0.5, \"frames\": [ { \"file_path\": \"./train/r_0\", \"transform_matrix\": [[NaN,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]] } ] }");
            Assert.That(double.IsNaN(doc.Frames[0].TransformMatrix.Value[0, 0]), Is.True);
        }

        [Test]
        public void MalformedJsonGivesLineAndColumn()
        {
            var e = Assert.Throws<SettingsFormatException>(() => TransformsReader.Read("{\n  \"camera_angle_x\": 0.5,\n  \"frames\": [\n}", "transforms_train.json"));
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Message, Does.StartWith("transforms_train.json(4,"));
        }

        [Test]
        public void AnEmptyTransformsFileSaysWhatItShouldHold()
        {
            var e = Assert.Throws<SettingsFormatException>(() => TransformsReader.Read("", "transforms_val.json"));
            Assert.That(e.Message, Does.StartWith("transforms_val.json: the file is empty. A transforms file is a JSON object with camera_angle_x and frames"));
        }

        [Test]
        public void TextAfterTheObjectIsMalformed()
        {
            // The original plugin appended a second object on every run.
            Assert.Throws<SettingsFormatException>(() => TransformsReader.Read("{ \"camera_angle_x\": 0.5, \"frames\": [] }{ \"camera_angle_x\": 0.5, \"frames\": [] }"));
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
                TransformsDocument whole = null, streamed = null;
                SettingsFormatException wholeError = null, streamedError = null;
                var frames = new List<TransformsFrame>();
                try { whole = TransformsReader.ReadFile(path); } catch (SettingsFormatException e) { wholeError = e; }
                try { streamed = TransformsReader.ReadFile(path, (f, json) => frames.Add(f)); } catch (SettingsFormatException e) { streamedError = e; }
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
                    Assert.That(frames[i].ExtraFiles, Is.EqualTo(whole.Frames[i].ExtraFiles));
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
