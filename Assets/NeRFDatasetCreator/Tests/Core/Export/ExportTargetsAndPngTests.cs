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
        // The config's loader names (TargetLoaderNames): 3DGS reads a COLMAP source, instant-ngp the ngp export.
        [TestCase("3dgs", ExportTarget.Colmap)]
        [TestCase("3DGS", ExportTarget.Colmap)]
        [TestCase("instant-ngp", ExportTarget.Ngp)]
        [TestCase("gsplat", ExportTarget.Colmap)]
        public void Parse_KnownNames(string value, ExportTarget expected)
        {
            Assert.That(ExportTargets.Parse(value, out var problem), Is.EqualTo(expected));
            Assert.That(problem, Is.Null);
        }

        [Test]
        public void Parse_UnknownName_ListsTheValidOnes()
        {
            Assert.That(ExportTargets.Parse("obj", out var problem), Is.Null);
            Assert.That(problem.Field, Is.EqualTo("--to"));
            Assert.That(problem.Fix, Is.EqualTo("Use one of: nerfstudio, colmap, ngp, dynamic3dgs, gaussian-grouping, nerfies, dycheck, llff, dynerf, neus, replica, tum, multiscale, hdr-nerf, tensoir, gs-ir, r3dg, kubric, nsff, shape-of-motion (or the trainers' names 3dgs = gsplat = colmap, instant-ngp = ngp)."));
        }

        [TestCase("3dsg", "3dgs")]
        [TestCase("instantngp", "instant-ngp")]
        [TestCase("colmp", "colmap")]
        [TestCase("nerfstduio", "nerfstudio")]
        public void Parse_NearMiss_SuggestsTheName(string value, string suggested)
        {
            Assert.That(ExportTargets.Parse(value, out var problem), Is.Null);
            Assert.That(problem.Fix, Does.EndWith(" Did you mean \"" + suggested + "\"?"));
        }

        [TestCase("nerf")]
        [TestCase("blender")]
        public void Parse_TheDatasetsOwnFormat_SaysNoConversionIsNeeded(string value)
        {
            Assert.That(ExportTargets.Parse(value, out var problem), Is.Null);
            Assert.That(problem.Reason, Does.Contain("already in"));
            Assert.That(problem.Fix, Does.StartWith("Point the trainer at the dataset folder"));
        }
    }
}
