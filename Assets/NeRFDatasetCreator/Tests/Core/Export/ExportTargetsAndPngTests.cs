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
            Assert.That(problem.Fix, Is.EqualTo("Use one of: nerfstudio, colmap, ngp, dynamic3dgs, gaussian-grouping."));
        }
    }
}
