using System;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class ExportTargetsAndPngTests
    {
        [TestCase("nerfstudio", ExportTarget.Nerfstudio)]
        [TestCase("COLMAP", ExportTarget.Colmap)]
        [TestCase(" ngp ", ExportTarget.Ngp)]
        public void Parse_KnownNames(string value, ExportTarget expected)
        {
            Assert.That(ExportTargets.Parse(value, out var problem), Is.EqualTo(expected));
            Assert.That(problem, Is.Null);
        }

        [Test]
        public void Parse_UnknownName_ListsTheValidOnes()
        {
            Assert.That(ExportTargets.Parse("blender", out var problem), Is.Null);
            Assert.That(problem.Field, Is.EqualTo("--to"));
            Assert.That(problem.Fix, Is.EqualTo("Use one of: nerfstudio, colmap, ngp."));
        }

        [Test]
        public void PngHeader_ReadsSizeDepthAndColourType()
        {
            var path = Path.Combine(Path.GetTempPath(), "nerf-png-" + Guid.NewGuid().ToString("N") + ".png");
            try
            {
                TestPng.Write(path, 37, 21, 16, TestPng.ColorTypeGrey);
                var h = PngHeader.Read(path);
                Assert.That(new[] { h.Width, h.Height, h.BitDepth, h.ColorType }, Is.EqualTo(new[] { 37, 21, 16, 0 }));

                File.WriteAllText(path, "not a png at all, just some text");
                var e = Assert.Throws<InvalidParameterException>(() => PngHeader.Read(path));
                Assert.That(e.Problems[0].Field, Is.EqualTo("file_path"));
            }
            finally
            {
                File.Delete(path);
            }
        }
    }
}
