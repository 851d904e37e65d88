using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// dynamic-capture.md's worked example: nerf-sample-multiview.json, as shipped (its val split is empty), planned
    /// with what Unity measures for the sample's animated target, written with an image for every view, then
    /// <c>convert --to dynamic3dgs</c> — which must give the layout the page describes.
    /// </summary>
    [TestFixture]
    public class SampleConvertTests
    {
        string _folder;

        [SetUp]
        public void SetUp() => _folder = Path.Combine(Path.GetTempPath(), "nerf-sample-convert-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        [Test]
        public void TheMultiViewSampleWithItsEmptyValSplitValidatesAndConvertsToDynamic3dgs()
        {
            var settings = DatasetSettingsJson.ReadFile(RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", "nerf-sample-multiview.json")).Settings;
            Assert.That(settings.Val.Count, Is.EqualTo(0), "the sample ships with an empty val split");
            var plan = CapturePlan.Build(settings, SampleTests.AnimatedTargetAsUnityMeasuresIt());
            var dataset = Path.Combine(_folder, "nerf-sample-multiview");
            Write(dataset, plan);

            var report = DatasetValidator.Validate(dataset);
            Assert.That(report.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(report.FrameCounts["val"], Is.EqualTo(0));

            var result = DatasetConverter.Convert(dataset, ExportTarget.Dynamic3dgs);
            var outDir = Path.Combine(dataset, Dynamic3DGaussians.FolderName);
            Assert.That(result.MainFile, Is.EqualTo(Path.Combine(outDir, "train_meta.json")));
            // "12 train cameras × 21 steps, 2 test cameras × 21": fn[t][c] for every step and camera.
            var train = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "train_meta.json")));
            Assert.That(train["fn"].Count(), Is.EqualTo(21));
            Assert.That(train["fn"].All(step => step.Count() == 12), Is.True);
            var test = JObject.Parse(File.ReadAllText(Path.Combine(outDir, "test_meta.json")));
            Assert.That(test["fn"].Count(), Is.EqualTo(21));
            Assert.That(test["fn"].All(step => step.Count() == 2), Is.True);
            Assert.That(File.Exists(Path.Combine(outDir, "init_pt_cld.npz")), Is.True);
            // "val is empty, so nothing is left out": no warning about val frames the layout cannot hold.
            Assert.That(result.Warnings.Where(w => w.Field == "val").Select(w => w.ToString()), Is.Empty);
            Assert.That(Directory.GetFiles(Path.Combine(outDir, "ims"), "*.png", SearchOption.AllDirectories).Length, Is.EqualTo(21 * 14));
        }

        /// <summary>The plan's files through a write session, a blank 8-bit RGBA image per view, and a recorded points3d.ply.</summary>
        static void Write(string folder, CapturePlan plan)
        {
            var w = plan.Intrinsics.Width;
            var h = plan.Intrinsics.Height;
            var image = PngWriter.Encode(new byte[w * h * 4], w, h, PngPixelFormat.Rgba8);
            var session = DatasetWriteSession.Begin(folder, OverwritePolicy.Never);
            foreach (var file in plan.Views.SelectMany(v => v.Files))
            {
                Assert.That(file.Kind, Is.EqualTo(DatasetFileKind.Color), "the sample captures colour only");
                var path = session.PathOf(file.RelativePath);
                Directory.CreateDirectory(Path.GetDirectoryName(path));
                File.WriteAllBytes(path, image);
            }
            DatasetMetadataFiles.Write(session, plan, new Provenance(new DateTime(2026, 1, 2, 3, 4, 5, DateTimeKind.Utc)));
            session.Commit();
            // The capture samples the target's surface; two points stand in for the sample's 20 000.
            var cloud = new[] { new CloudPoint(new Vector3d(0.1, 0.2, 0.3), Vector3d.UnitZ, 255, 0, 0), new CloudPoint(new Vector3d(0, 0, -0.2), Vector3d.UnitZ, 0, 255, 0) };
            var ply = Path.Combine(folder, PointCloudOwnership.FileName);
            PlyWriter.Write(ply, cloud);
            var configPath = Path.Combine(folder, DatasetLayout.ConfigFileName);
            var config = JObject.Parse(File.ReadAllText(configPath));
            config[PointCloudRecord.Key] = PointCloudRecord.Of(ply, PointCloudOwnership.FileName, cloud.Length).ToJson();
            File.WriteAllText(configPath, config.ToString());
        }
    }
}
