using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A run's matting diagnostics: the writer adds every view's counts, the tally sums them, lists the views above the
    /// threshold in plan order, words the warning and fills dataset_config.json's statistics.
    /// </summary>
    public class MattingTallyTests
    {
        static readonly PlanTarget Target = new PlanTarget(new Vector3d(1, 2, 3), 0.5);
        TempFolder _temp;

        [SetUp]
        public void CreateProject() => _temp = new TempFolder();

        [TearDown]
        public void DeleteProject() => _temp.Dispose();

        static MattingDiagnostics View(long darker, long stray) =>
            new MattingDiagnostics { Samples = 10000, DarkerOverWhite = darker, StrayBackground = stray, BackgroundChecked = true };

        [Test]
        public void SumsEveryViewAndListsOnlyThoseAboveTheThresholdInPlanOrder()
        {
            var tally = new MattingTally();
            tally.Add(DatasetSplit.Test, 0, View(0, 50));   // 0.5 % stray
            tally.Add(DatasetSplit.Train, 7, View(10, 0));  // 0.1 %: not above
            tally.Add(DatasetSplit.Train, 3, View(11, 0));  // 0.11 %
            tally.Add(DatasetSplit.Val, 1, View(0, 0));
            Assert.That(tally.Total.Samples, Is.EqualTo(40000));
            Assert.That(tally.Total.DarkerOverWhite, Is.EqualTo(21));
            Assert.That(tally.Total.StrayBackground, Is.EqualTo(50));
            Assert.That(tally.ViewsCounted, Is.EqualTo(4));
            Assert.That(tally.ViewsAboveThreshold, Is.EqualTo(2));
            var lines = tally.ViewLines();
            Assert.That(lines.Select(l => l.Substring(0, l.IndexOf(':'))), Is.EqualTo(new[] { "train r_3", "test r_0" }));
            Assert.That(lines[0], Does.StartWith("train r_3: 11 of 10000 samples (0.11 %) darker over white"));
            var warning = tally.Warning();
            Assert.That(warning, Does.Contain("2 of 4 views").And.Contain("train r_3").And.Contain("Full Screen Pass"));

            var statistics = new Dictionary<string, double>();
            tally.WriteStatistics(statistics);
            Assert.That(statistics, Is.EquivalentTo(new Dictionary<string, double>
            {
                ["mattingSamples"] = 40000, ["mattingDarkerOverWhiteSamples"] = 21, ["mattingStrayBackgroundSamples"] = 50, ["mattingViewsAboveThreshold"] = 2,
            }));
        }

        [Test]
        public void KeepsTheFirstViewsByNameAndCountsTheRest()
        {
            var tally = new MattingTally();
            for (int i = 40; i >= 0; i--) tally.Add(DatasetSplit.Train, i, View(100, 0));
            Assert.That(tally.ViewsAboveThreshold, Is.EqualTo(41));
            var lines = tally.ViewLines();
            Assert.That(lines.Count, Is.EqualTo(MattingTally.MaxListedViews));
            Assert.That(lines.First(), Does.StartWith("train r_0:"));
            Assert.That(lines.Last(), Does.StartWith("train r_19:"));
            Assert.That(tally.Warning(), Does.Contain("… and 21 more."));
        }

        [Test]
        public void NoWarningAndNoStrayFigureWithoutAMask()
        {
            var tally = new MattingTally();
            tally.Add(DatasetSplit.Train, 0, new MattingDiagnostics { Samples = 10000, DarkerOverWhite = 1 });
            Assert.That(tally.Warning(), Is.Null);
            var statistics = new Dictionary<string, double>();
            tally.WriteStatistics(statistics);
            Assert.That(statistics.Keys, Is.EquivalentTo(new[] { "mattingSamples", "mattingDarkerOverWhiteSamples", "mattingViewsAboveThreshold" }));
        }

        [Test]
        public void TheWriterCountsEveryViewItMattes()
        {
            var settings = new DatasetSettings { Name = "unit", Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K };
            settings.Train.Count = 3;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            var run = DatasetRun.Prepare(settings, Target, _temp.Path);
            Assert.That(run.Problems, Is.Empty);
            var session = run.Begin();
            var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
            var views = run.Plan.Views;
            writer.Write(views[0], SyntheticViews.MattedColour(), SyntheticViews.Data());
            // A vignette-like veil: the white background dimmed to 0.9 in every sample outside the geometry.
            var veiled = SyntheticViews.MattedColour();
            int veiledSamples = 0;
            for (int i = 0; i < veiled.Mask.Length; i++)
                if (veiled.Mask[i] == 0)
                {
                    veiledSamples++;
                    for (int c = 0; c < 3; c++) veiled.ColorOverWhite[i * 4 + c] = 0x3B33; // 0.9
                }
            writer.Write(views[1], veiled, SyntheticViews.Data());
            writer.Write(views[2], SyntheticViews.Colour(), SyntheticViews.Data()); // one render + mask: no matting, not counted
            int samples = SyntheticViews.Width * SyntheticViews.K * SyntheticViews.Height * SyntheticViews.K;
            Assert.That(veiledSamples, Is.EqualTo(15 * 16), "raw columns 9–23 (output columns 5–11 and the right half of 4), 16 rows");
            Assert.That(writer.Matting.ViewsCounted, Is.EqualTo(2));
            Assert.That(writer.Matting.Total.Samples, Is.EqualTo(2 * samples));
            Assert.That(writer.Matting.Total.StrayBackground, Is.EqualTo(veiledSamples));
            Assert.That(writer.Matting.Total.DarkerOverWhite, Is.EqualTo(0));
            Assert.That(writer.Matting.ViewLines().Single(), Does.StartWith(views[1].Split.ToString().ToLowerInvariant() + " r_" + views[1].Index + ":"));
        }
    }
}
