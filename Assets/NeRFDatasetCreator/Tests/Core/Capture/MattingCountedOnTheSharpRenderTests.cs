using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32, R4-3: the matting diagnostics of a blurred or lens view are counted on the render its mask belongs to —
    /// the sharp mid-pose render, before a lens resamples it — so a clean scene reports no stray background whatever the
    /// blur or the lens, while a stray sample in that render is still reported.
    /// </summary>
    [TestFixture]
    public class MattingCountedOnTheSharpRenderTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        static MattingTally Tally(string project, string name, AnalyticDataset.Options options)
        {
            MattingTally tally = null;
            options.AfterViews = pipeline => tally = pipeline.Files.Matting;
            AnalyticDataset.Write(project, name, options);
            return tally;
        }

        [Test]
        public void ABlurredCaptureOfACleanSceneReportsNoStrayBackground()
        {
            // A 0.3-unit shake over 8 sub-frames: the blurred silhouettes spread several samples beyond the mid-pose mask.
            var options = new AnalyticDataset.Options
            {
                Width = 48, Height = 36, Train = 3, Val = 1, Test = 1, PointCloud = 0,
                MotionBlur = new MotionBlurSettings { Enabled = true, Camera = ShutterCameraMotion.Shake, ShakeDistance = 0.3, ShakeDegrees = 2, SubFrames = 8 },
            };
            var tally = Tally(_temp.Path, "blur", options);
            Assert.That(tally.ViewsCounted, Is.EqualTo(5), "one count per view, not one per written image");
            Assert.That(tally.Total.Samples, Is.EqualTo(5L * 96 * 72), "the samples of the sharp renders");
            Assert.That(tally.Total.BackgroundChecked, Is.True, "the mask pass ran");
            Assert.That(tally.Total.StrayBackground, Is.EqualTo(0), "the mid-pose render matches its mask");
            Assert.That(tally.ViewsAboveThreshold, Is.EqualTo(0));
            Assert.That(tally.Warning(), Is.Null);
        }

        [Test]
        public void ALensCaptureIsCountedOnTheWideRenderBeforeResampling()
        {
            var options = new AnalyticDataset.Options
            {
                Width = 48, Height = 36, Train = 3, Val = 1, Test = 1, PointCloud = 0,
                Lens = new LensSettings { Model = "opencv", K1 = -0.25, K2 = 0.06, P1 = 0.003, P2 = -0.002 },
                ThroughWideRender = true, VerticalFovDegrees = 70, Distance = 1.8,
            };
            LensPinholeCover wide = null;
            MattingTally tally = null;
            options.AfterViews = pipeline =>
            {
                wide = pipeline.WideRender;
                tally = pipeline.Files.Matting;
            };
            AnalyticDataset.Write(_temp.Path, "lens", options);
            Assert.That(wide, Is.Not.Null);
            Assert.That(wide.Width * wide.Height, Is.GreaterThan(48 * 36), "the wide render covers more than the output frame");
            Assert.That(tally.ViewsCounted, Is.EqualTo(5));
            Assert.That(tally.Total.Samples, Is.EqualTo(5L * wide.Width * 2 * wide.Height * 2), "the samples of the wide renders");
            Assert.That(tally.Total.StrayBackground, Is.EqualTo(0), "the wide render matches its mask");
            Assert.That(tally.ViewsAboveThreshold, Is.EqualTo(0));
        }

        /// <summary>One train view at 12×8 (k = 2), the synthetic glass picture; its pipeline.</summary>
        static (ViewPipeline Pipeline, PlannedView View, DatasetWriteSession Session) OneView(string project, string name)
        {
            var settings = new DatasetSettings { Name = name, Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K };
            foreach (var split in new[] { settings.Train, settings.Val, settings.Test }) split.Count = 1;
            settings.Train.Mask = true;
            var run = DatasetRun.Prepare(settings, new PlanTarget(AnalyticDataset.Centre, 1.2), project);
            Assert.That(run.Problems, Is.Empty, "the test's settings");
            var session = run.Begin();
            return (new ViewPipeline(run.Plan, session, null, null), run.Plan.Views.First(v => v.Split == DatasetSplit.Train), session);
        }

        /// <summary>The glass picture with <paramref name="count"/> background samples (mask 0) that are not the clear pair.</summary>
        static RawFrame WithStray(int count)
        {
            var frame = SyntheticViews.MattedColour();
            var planted = 0;
            for (var i = frame.Mask.Length - 1; i >= 0 && planted < count; i--)
            {
                if (frame.Mask[i] != 0) continue;
                frame.ColorOverBlack[i * 4] = 0x3400; // 0.25 over black where nothing was drawn
                planted++;
            }
            return frame;
        }

        [TestCase(0, 3, 0)]
        [TestCase(2, 0, 2)]
        [TestCase(2, 3, 2)]
        public void ABlurredViewCountsTheStraySamplesOfItsSharpRenderOnly(int strayInSharp, int strayInBlurred, int expected)
        {
            var (pipeline, view, session) = OneView(_temp.Path, "planted");
            pipeline.Write(view, WithStray(strayInSharp), SyntheticViews.Data(), WithStray(strayInBlurred));
            session.End();
            var total = pipeline.Files.Matting.Total;
            Assert.That(pipeline.Files.Matting.ViewsCounted, Is.EqualTo(1));
            Assert.That(total.Samples, Is.EqualTo(24L * 16));
            Assert.That(total.StrayBackground, Is.EqualTo(expected));
        }

        [Test]
        public void ASharpViewWithoutLensStillCountsItsOwnRender()
        {
            var (pipeline, view, session) = OneView(_temp.Path, "sharp");
            pipeline.Write(view, WithStray(3), SyntheticViews.Data());
            session.End();
            Assert.That(pipeline.Files.Matting.ViewsCounted, Is.EqualTo(1));
            Assert.That(pipeline.Files.Matting.Total.StrayBackground, Is.EqualTo(3));
        }
    }
}
