using System;
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
    }
}
