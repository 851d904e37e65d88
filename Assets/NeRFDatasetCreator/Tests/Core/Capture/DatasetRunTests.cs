using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetRunTests
    {
        static readonly PlanTarget Target = new PlanTarget(new Vector3d(1, 2, 3), 0.5);
        TempFolder _temp;
        string _project;

        [SetUp]
        public void CreateProject()
        {
            _temp = new TempFolder();
            _project = _temp.Path;
        }

        [TearDown]
        public void DeleteProject() => _temp.Dispose();

        static DatasetSettings Settings(int train = 2, int val = 1, int test = 1)
        {
            var settings = new DatasetSettings { Name = "unit", Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K };
            settings.Train.Count = train;
            settings.Val.Count = val;
            settings.Test.Count = test;
            settings.Test.Depth = ExtraOutput.PngAndExr;
            settings.Test.Normal = ExtraOutput.PngAndExr;
            settings.Test.Mask = true;
            return settings;
        }

        static string Capture(DatasetRun run, Action<DatasetWriteSession> beforeFinish = null)
        {
            Assert.That(run.Problems, Is.Empty);
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            foreach (var view in run.Plan.Views)
                writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
            beforeFinish?.Invoke(session);
            run.Finish(session, new Provenance(new DateTime(2026, 11, 22, 12, 0, 0, DateTimeKind.Utc), "6000.0.0f1", "unit-test"));
            return run.DatasetFolder;
        }

        [Test]
        public void ARunWritesADatasetTheValidatorAccepts()
        {
            var folder = Capture(DatasetRun.Prepare(Settings(), Target, _project));

            var report = DatasetValidator.Validate(folder);
            Assert.That(report.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(report.FrameCounts["train"], Is.EqualTo(2));
            Assert.That(report.ImageWidth, Is.EqualTo(SyntheticViews.Width));
            Assert.That(folder, Is.EqualTo(Path.Combine(_project, "NeRFDatasets", "unit")));
            Assert.That(Directory.GetDirectories(Path.GetDirectoryName(folder)), Has.Length.EqualTo(1), "no partial folder is left behind");
        }

        [Test]
        public void AWholeDatasetHasItsRigPictureAndAShardHasNone()
        {
            var folder = Capture(DatasetRun.Prepare(Settings(), Target, _project));
            var picture = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(folder, RigPreviewPicture.FileName)));
            Assert.That(new[] { picture.Width, picture.Height, picture.ColorType }, Is.EqualTo(new[] { RigPreviewPicture.Width, RigPreviewPicture.Height, 2 }));
            var shard = Capture(DatasetRun.Prepare(Settings(train: 4), Target, _project, new ShardSpec(0, 2), "shard-0"));
            Assert.That(File.Exists(Path.Combine(shard, RigPreviewPicture.FileName)), Is.False, "merge carries no per-shard picture");
        }

        [Test]
        public void ColourHasStraightAlphaAndTheTopRowComesFirst()
        {
            var folder = Capture(DatasetRun.Prepare(Settings(), Target, _project));
            var png = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(folder, "train", "r_0.png")));
            Assert.That(new[] { png.Width, png.Height, png.BitDepth, png.ColorType }, Is.EqualTo(new[] { 12, 8, 8, 6 }));
            byte[] Pixel(int x, int y) => png.Pixels.Skip((y * png.Width + x) * 4).Take(4).ToArray();
            Assert.That(Pixel(0, 0), Is.EqualTo(new byte[] { 200, 100, 50, 255 }));
            Assert.That(Pixel(4, 3), Is.EqualTo(new byte[] { 200, 100, 50, 128 }), "a half-covered edge keeps its full colour");
            Assert.That(Pixel(6, 5), Is.EqualTo(new byte[] { 0, 0, 0, 0 }));
        }

        [Test]
        public void DepthNormalAndMaskFilesHoldTheDocumentedEncodings()
        {
            var folder = Capture(DatasetRun.Prepare(Settings(), Target, _project));
            var depth = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(folder, "test", "r_0_depth_0000.png")));
            Assert.That(new[] { depth.BitDepth, depth.ColorType }, Is.EqualTo(new[] { 16, 0 }));
            int Millimetres(int x, int y) => depth.Pixels[(y * depth.Width + x) * 2] << 8 | depth.Pixels[(y * depth.Width + x) * 2 + 1];
            Assert.That(Millimetres(0, 0), Is.EqualTo(2700), "the top row is the last readback row: 2 m + 7·0.1 m");
            Assert.That(Millimetres(0, 7), Is.EqualTo(2000));
            Assert.That(Millimetres(7, 0), Is.EqualTo(0), "no surface");

            var normal = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(folder, "test", "r_0_normal_0000.png")));
            Assert.That(normal.Pixels.Take(3).ToArray(), Is.EqualTo(new byte[] { 128, 128, 255 }), "+Z up encodes as n·0.5+0.5");
            var mask = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(folder, "test", "r_0_mask_0000.png")));
            Assert.That(new[] { mask.Pixels[0], mask.Pixels[4], mask.Pixels[7] }, Is.EqualTo(new byte[] { 255, 128, 0 }));

            Assert.That(File.ReadAllBytes(Path.Combine(folder, "test", "r_0_depth_0000.exr")), Is.EqualTo(new byte[] { (byte)'E', (byte)'X', (byte)'R', 1 }));
            Assert.That(File.ReadAllBytes(Path.Combine(folder, "test", "r_0_normal_0000.exr")), Is.EqualTo(new byte[] { (byte)'E', (byte)'X', (byte)'R', 4 }));
            Assert.That(File.Exists(Path.Combine(folder, "train", "r_0_depth_0000.png")), Is.False, "train asked for no depth");
        }

        [Test]
        public void WithTheMattingPairAlphaIsTheGlassOpacityAndTheMaskItsGeometry()
        {
            var run = DatasetRun.Prepare(Settings(), Target, _project);
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            foreach (var view in run.Plan.Views)
                writer.Write(view, SyntheticViews.MattedColour(), SyntheticViews.Data());
            run.Finish(session, new Provenance(new DateTime(2026, 11, 22, 12, 0, 0, DateTimeKind.Utc), "6000.0.0f1", "unit-test"));

            var png = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(run.DatasetFolder, "test", "r_0.png")));
            byte[] Pixel(int x, int y) => png.Pixels.Skip((y * png.Width + x) * 4).Take(4).ToArray();
            // Linear 0.5 → sRGB 188; alpha 0.5 → 128; the half-covered edge: 2 of 4 samples at 0.5 → 0.25 → 64.
            Assert.That(Pixel(0, 0), Is.EqualTo(new byte[] { 188, 188, 188, 128 }));
            Assert.That(Pixel(4, 3), Is.EqualTo(new byte[] { 188, 188, 188, 64 }));
            Assert.That(Pixel(6, 5), Is.EqualTo(new byte[] { 0, 0, 0, 0 }));
            var mask = ReferencePngDecoder.Decode(File.ReadAllBytes(Path.Combine(run.DatasetFolder, "test", "r_0_mask_0000.png")));
            Assert.That(new[] { mask.Pixels[0], mask.Pixels[4], mask.Pixels[7] }, Is.EqualTo(new byte[] { 255, 128, 0 }),
                "the mask is where the geometry is, whatever its opacity");
        }

        [Test]
        public void TheWrittenMatricesAreThePlans()
        {
            var run = DatasetRun.Prepare(Settings(), Target, _project);
            var folder = Capture(run);
            var frames = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["frames"];
            var planned = run.Plan.ViewsOf(DatasetSplit.Train).ToList();
            for (var i = 0; i < planned.Count; i++)
            {
                var written = frames[i]["transform_matrix"].ToObject<double[][]>();
                for (var r = 0; r < 4; r++)
                    for (var c = 0; c < 4; c++)
                        Assert.That(written[r][c], Is.EqualTo(planned[i].TransformMatrix[r, c]));
            }
        }

        [Test]
        public void NothingIsUnderTheFinalNameUntilTheRunFinishes()
        {
            var run = DatasetRun.Prepare(Settings(), Target, _project);
            Capture(run, session =>
            {
                Assert.That(Directory.Exists(run.DatasetFolder), Is.False);
                Assert.That(File.Exists(Path.Combine(session.WorkingFolder, "train", "r_1.png")), Is.True);
                Assert.That(File.Exists(Path.Combine(session.WorkingFolder, "transforms_train.json")), Is.False, "JSON is written last");
            });
            Assert.That(Directory.Exists(run.DatasetFolder), Is.True);
        }

        [Test]
        public void ASecondRunNeverOverwritesTheFirst()
        {
            Capture(DatasetRun.Prepare(Settings(), Target, _project));
            var again = DatasetRun.Prepare(Settings(), Target, _project);
            Assert.That(again.IsValid, Is.False);
            Assert.That(again.Problems.Select(p => p.Field), Does.Contain("overwrite"), "the default policy is never");
        }

        [Test]
        public void DepthBeyondSixtyFiveMetresIsClampedAndCounted()
        {
            var run = DatasetRun.Prepare(Settings(train: 1, val: 1, test: 1), Target, _project);
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            writer.Write(run.Plan.ViewsOf(DatasetSplit.Test).Single(), SyntheticViews.Colour(), SyntheticViews.Data(extraMetres: 70));
            Assert.That(writer.ClampedDepthPixels, Is.EqualTo(5 * 8), "the 5 covered columns of 8 rows");
            session.DiscardPartialFiles();
        }

        [Test]
        public void AShardWithoutViewsOfASplitStillDeclaresItsDepthScale()
        {
            // Test views 8 and 9 (global order) go to shards 2 and 0: shard 1 renders no test view.
            var run = DatasetRun.Prepare(Settings(train: 5, val: 3, test: 2), Target, _project, new ShardSpec(1, 3), "shard-1");
            Assert.That(run.Plan.ViewsOf(DatasetSplit.Test), Is.Empty);
            var test = JObject.Parse(File.ReadAllText(Path.Combine(Capture(run), "transforms_test.json")));
            Assert.That((double)test["integer_depth_scale"], Is.EqualTo(0.001));
            Assert.That(test["frames"], Is.Empty);
        }

        [Test]
        public void ShardsMergeIntoTheWholeDataset()
        {
            var settings = Settings(train: 5, val: 3, test: 2);
            var shardFolders = new List<string>();
            var seen = new List<string>();
            for (var i = 0; i < 3; i++)
            {
                var run = DatasetRun.Prepare(settings, Target, _project, new ShardSpec(i, 3), Path.Combine("shards", "shard-" + i));
                seen.AddRange(run.Plan.Views.Select(v => v.FramePath));
                shardFolders.Add(Capture(run));
                Assert.That(File.Exists(Path.Combine(shardFolders[i], ShardManifest.FileName)), Is.True);
            }
            Assert.That(seen, Is.EquivalentTo(DatasetRun.Prepare(settings, Target, _project).Plan.Views.Select(v => v.FramePath)),
                "every view is rendered by exactly one shard");

            var merged = Path.Combine(_project, "merged");
            var result = ShardMerger.Merge(shardFolders, merged);
            Assert.That(result.Problems.Select(p => p.ToString()), Is.Empty);
            var report = DatasetValidator.Validate(merged);
            Assert.That(report.Problems.Select(p => p.ToString()), Is.Empty);
            Assert.That(new[] { report.FrameCounts["train"], report.FrameCounts["val"], report.FrameCounts["test"] }, Is.EqualTo(new[] { 5, 3, 2 }));
        }

        [Test]
        public void EveryProblemIsReportedBeforeAnythingIsWritten()
        {
            var settings = Settings();
            settings.Distance = 0.4; // inside the target's bounding sphere (radius 0.5)
            Directory.CreateDirectory(Path.Combine(_project, "Assets"));
            Directory.CreateDirectory(Path.Combine(_project, "ProjectSettings"));
            var run = DatasetRun.Prepare(settings, Target, _project, new ShardSpec(1, 3), Path.Combine("Assets", "Data"));
            Assert.That(run.IsValid, Is.False);
            Assert.That(run.Problems.Select(p => p.Field), Is.SupersetOf(new[] { "distance", "outputFolder" }));
            Assert.That(run.Plan, Is.Null);
            Assert.That(Directory.Exists(Path.Combine(_project, "Assets", "Data")), Is.False);
            Assert.Throws<InvalidParameterException>(() => run.Begin());
        }
    }
}
