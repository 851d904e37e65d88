using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Each trainer's layout, made exactly as its code writes it (see RenderLayouts.Source for file and line), is found
    /// and paired with the split's frames; counts and names that do not match the split are refused.
    /// </summary>
    public class RenderFolderTests
    {
        static readonly string[] Frames = { "./test/r_0", "./test/r_1", "./test/r_2" };

        static void Png(string path, int w = 4, int h = 3, int colorType = PngInfo.ColorTypeRgb)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            TestPng.Write(path, w, h, 8, colorType);
        }

        /// <summary>3DGS render.py: &lt;model&gt;/test/ours_&lt;iter&gt;/renders/{idx:05d}.png and gt/ beside it.</summary>
        static string GaussianModel(TempFolder temp, int count, params int[] iterations)
        {
            var model = temp.Combine("output", "lego");
            foreach (var iteration in iterations)
                for (var i = 0; i < count; i++)
                {
                    Png(Path.Combine(model, "test", "ours_" + iteration, "renders", i.ToString("00000") + ".png"));
                    Png(Path.Combine(model, "test", "ours_" + iteration, "gt", i.ToString("00000") + ".png"));
                }
            Png(Path.Combine(model, "train", "ours_" + iterations[0], "renders", "00000.png"));
            File.WriteAllText(Path.Combine(model, "cfg_args"), "Namespace()");
            return model;
        }

        [Test]
        public void GaussianSplattingRendersAreReadInFrameOrderFromTheLatestIteration()
        {
            using (var temp = new TempFolder())
            {
                var model = GaussianModel(temp, 3, 7000, 30000);
                var set = RenderFolder.Read(model, null, "test", Frames);
                Assert.That(set.Layout, Is.EqualTo(RenderLayout.GaussianSplatting));
                Assert.That(set.Views.Select(v => Path.GetFileName(v.ColourPath)), Is.EqualTo(new[] { "00000.png", "00001.png", "00002.png" }));
                Assert.That(set.Views.Select(v => v.FramePath), Is.EqualTo(Frames));
                Assert.That(set.Folder, Does.EndWith(Path.Combine("ours_30000", "renders")));
                Assert.That(set.Notes.Single(), Does.Contain("ours_30000"));
                // The ours_<iter> folder itself picks that iteration.
                var older = RenderFolder.Read(Path.Combine(model, "test", "ours_7000"), RenderLayout.GaussianSplatting, "test", Frames);
                Assert.That(older.Folder, Does.EndWith(Path.Combine("ours_7000", "renders")));
            }
        }

        [Test]
        public void GaussianSplattingWithAnotherCountIsRefused()
        {
            using (var temp = new TempFolder())
            {
                var model = GaussianModel(temp, 2, 30000);
                Assert.That(() => RenderFolder.Read(model, null, "test", Frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("holds 2 renders (00000.png … 00001.png) but transforms_test.json lists 3 frames"));
                Assert.That(() => RenderFolder.Read(model, RenderLayout.GaussianSplatting, "val", Frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("never renders val"));
            }
        }

        /// <summary>nerf-pytorch run_nerf.py: &lt;basedir&gt;/&lt;expname&gt;/testset_{:06d}/'{:03d}'.png over poses[i_test] (RenderLayouts.Source).</summary>
        static void NerfPytorchRenders(string folder, int count)
        {
            for (var i = 0; i < count; i++) Png(Path.Combine(folder, i.ToString("000") + ".png"));
        }

        [Test]
        public void NerfPytorchRendersAreReadInFrameOrderFromTheLatestIteration()
        {
            using (var temp = new TempFolder())
            {
                var experiment = temp.Combine("logs", "lego");
                NerfPytorchRenders(Path.Combine(experiment, "testset_050000"), 3);
                NerfPytorchRenders(Path.Combine(experiment, "testset_200000"), 3);
                NerfPytorchRenders(Path.Combine(experiment, "renderonly_test_200000"), 3);
                File.WriteAllText(Path.Combine(experiment, "renderonly_test_200000", "video.mp4"), "");
                File.WriteAllText(Path.Combine(experiment, "args.txt"), "");
                var set = RenderFolder.Read(experiment, null, "test", Frames);
                Assert.That(set.Layout, Is.EqualTo(RenderLayout.NerfPytorch));
                // The latest iteration, and at one iteration the render-only pass made from the saved weights.
                Assert.That(set.Folder, Does.EndWith("renderonly_test_200000"));
                Assert.That(set.Views.Select(v => Path.GetFileName(v.ColourPath)), Is.EqualTo(new[] { "000.png", "001.png", "002.png" }));
                Assert.That(set.Views.Select(v => v.FramePath), Is.EqualTo(Frames));
                Assert.That(set.Notes.Single(), Does.Contain("testset_050000, testset_200000, renderonly_test_200000"));
                // One of the folders itself is that one.
                var earlier = RenderFolder.Read(Path.Combine(experiment, "testset_050000"), null, "test", Frames);
                Assert.That(earlier.Layout, Is.EqualTo(RenderLayout.NerfPytorch));
                Assert.That(earlier.Folder, Does.EndWith("testset_050000"));
                Assert.That(RenderLayouts.TryParse("nerf-pytorch", out var named) && named == RenderLayout.NerfPytorch, Is.True);
            }
        }

        [Test]
        public void NerfPytorchRendersOfEveryEighthTestViewAreRefusedNamingTestskip()
        {
            using (var temp = new TempFolder())
            {
                var experiment = temp.Combine("logs", "lego");
                // 20 test frames; nerf-pytorch's default --testskip 8 loads frames 0, 8 and 16 (load_blender.py lines 51-56).
                var frames = Enumerable.Range(0, 20).Select(i => "./test/r_" + i).ToArray();
                NerfPytorchRenders(Path.Combine(experiment, "testset_010000"), 3);
                Assert.That(() => RenderFolder.Read(experiment, null, "test", frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("holds 3 renders but transforms_test.json lists 20 frames — every 8th one, as nerf-pytorch's --testskip 8 loads them")
                        .And.Message.Contains("--testskip 1"));
                Assert.That(() => RenderFolder.Read(experiment, null, "val", frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("test split only"));
                File.WriteAllText(Path.Combine(experiment, "testset_010000", "r_0.png"), "");
                Assert.That(() => RenderFolder.Read(Path.Combine(experiment, "testset_010000"), RenderLayout.NerfPytorch, "test", frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("holds r_0.png, which nerf-pytorch does not write there"));
            }
        }

        [Test]
        public void ARefusalNamesFilesInReadingOrder()
        {
            using (var temp = new TempFolder())
            {
                var renders = temp.Combine("plain");
                foreach (var i in new[] { 0, 1, 2, 10, 9, 8, 7 }) Png(Path.Combine(renders, "r_" + i + ".png"));
                Assert.That(() => RenderFolder.Read(renders, null, "test", Frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("holds r_7.png, r_8.png, r_9.png and 1 more, which no frame"));
            }
            Assert.That(new[] { "r_10.png", "r_9.png", "r_009.png", "a", "r_1.png", "r_1b.png" }.OrderBy(n => n, FileNameOrder.Instance),
                Is.EqualTo(new[] { "a", "r_1.png", "r_1b.png", "r_009.png", "r_9.png", "r_10.png" }));
        }

        [Test]
        public void NerfstudioDatasetRendersArePairedByImageName()
        {
            using (var temp = new TempFolder())
            {
                // ns-render dataset --output-path renders: renders/test/<output name>/<image path relative to the split's common folder>.
                var output = temp.Combine("renders");
                foreach (var name in new[] { "r_0", "r_1", "r_2" })
                {
                    Png(Path.Combine(output, "test", "rgb", name + ".png"));
                    Png(Path.Combine(output, "test", "gt-rgb", name + ".png"));
                    Png(Path.Combine(output, "test", "depth", name + ".png"));
                    Directory.CreateDirectory(Path.Combine(output, "test", "raw-depth"));
                    NpyReaderTests.WriteNpyGz(Path.Combine(output, "test", "raw-depth", name + ".npy.gz"), new[] { 3, 4, 1 }, new float[12]);
                }
                var set = RenderFolder.Read(output, null, "test", Frames);
                Assert.That(set.Layout, Is.EqualTo(RenderLayout.Nerfstudio));
                Assert.That(set.Views.Select(v => Path.GetFileName(v.ColourPath)), Is.EqualTo(new[] { "r_0.png", "r_1.png", "r_2.png" }));
                Assert.That(set.Views.All(v => v.DepthFormat == RenderDataFormat.NpyGz && v.DepthPath.EndsWith(".npy.gz")), Is.True);
                Assert.That(set.Views.All(v => v.NormalPath == null), Is.True);
                // The split folder itself works too.
                Assert.That(RenderFolder.Read(Path.Combine(output, "test"), null, "test", Frames).Layout, Is.EqualTo(RenderLayout.Nerfstudio));
            }
        }

        [Test]
        public void NerfstudioJpegRendersAreRefusedWithTheFlagThatFixesThem()
        {
            using (var temp = new TempFolder())
            {
                var output = temp.Combine("renders");
                Directory.CreateDirectory(Path.Combine(output, "test", "rgb"));
                foreach (var name in new[] { "r_0", "r_1", "r_2" }) File.WriteAllBytes(Path.Combine(output, "test", "rgb", name + ".jpg"), new byte[] { 0xff, 0xd8 });
                Assert.That(() => RenderFolder.Read(output, null, "test", Frames), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("--image-format png"));
            }
        }

        [Test]
        public void InstantNgpScreenshotsAreNamedAfterEachFilePath()
        {
            using (var temp = new TempFolder())
            {
                // run.py: os.path.join(screenshot_dir, os.path.basename(f["file_path"])) + ".png" when extensionless; RGBA.
                var shots = temp.Combine("screenshots");
                foreach (var name in new[] { "r_0", "r_1", "r_2" }) Png(Path.Combine(shots, name + ".png"), colorType: PngInfo.ColorTypeRgba);
                var set = RenderFolder.Read(shots, RenderLayout.InstantNgp, "test", Frames);
                Assert.That(set.Layout, Is.EqualTo(RenderLayout.InstantNgp));
                Assert.That(set.Views.Select(v => Path.GetFileName(v.ColourPath)), Is.EqualTo(new[] { "r_0.png", "r_1.png", "r_2.png" }));
                File.Delete(Path.Combine(shots, "r_1.png"));
                Assert.That(() => RenderFolder.Read(shots, RenderLayout.InstantNgp, "test", Frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("has no render for 1 of the 3 frames").And.Message.Contains("r_1.png").And.Message.Contains("--screenshot_transforms"));
            }
        }

        [Test]
        public void PlainFoldersPickUpDepthAndNormalsAndRefuseStrangers()
        {
            using (var temp = new TempFolder())
            {
                var plain = temp.Combine("plain");
                foreach (var name in new[] { "r_0", "r_1", "r_2" })
                {
                    Png(Path.Combine(plain, name + ".png"));
                    TestPng.Write(Path.Combine(plain, name + "_depth_0000.png"), 4, 3, 16, PngInfo.ColorTypeGray);
                }
                var set = RenderFolder.Read(plain, null, "test", Frames);
                Assert.That(set.Layout, Is.EqualTo(RenderLayout.Plain));
                Assert.That(set.Views.All(v => v.DepthFormat == RenderDataFormat.PluginPng), Is.True);
                Png(Path.Combine(plain, "r_3.png"));
                Assert.That(() => RenderFolder.Read(plain, null, "test", Frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("holds r_3.png, which no frame of transforms_test.json names"));
            }
        }

        [Test]
        public void AFolderWithoutRendersNamesTheLayoutsItLookedFor()
        {
            using (var temp = new TempFolder())
                Assert.That(() => RenderFolder.Read(temp.Path, null, "test", Frames),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("test/ours_<iter>/renders/00000.png").And.Message.Contains("--layout"));
        }
    }
}
