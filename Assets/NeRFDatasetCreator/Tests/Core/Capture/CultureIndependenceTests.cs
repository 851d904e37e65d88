using System;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Every file a run writes is the same byte for byte whatever the machine's culture: the same run under the
    /// invariant culture and under German (decimal comma) must agree — transforms, config, settings, the rig
    /// preview and every export.
    /// </summary>
    [TestFixture]
    public class CultureIndependenceTests
    {
        string _root;

        [SetUp]
        public void CreateRoot() => _root = Path.Combine(Path.GetTempPath(), "nerf-culture-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void DeleteRoot()
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        [Test]
        public void ARunWritesTheSameBytesUnderADecimalCommaCulture()
        {
            var invariant = Run(CultureInfo.InvariantCulture, "invariant");
            var german = Run(new CultureInfo("de-DE"), "german");
            Assert.That(1.5.ToString(new CultureInfo("de-DE")), Is.EqualTo("1,5"), "the culture really uses a decimal comma here");

            var files = Directory.GetFiles(invariant, "*", SearchOption.AllDirectories)
                .Select(f => f.Substring(invariant.Length + 1))
                .Where(f => f.EndsWith(".json", StringComparison.Ordinal) || f.EndsWith(".txt", StringComparison.Ordinal) || f.EndsWith(".ply", StringComparison.Ordinal))
                .OrderBy(f => f, StringComparer.Ordinal)
                .ToList();
            Assert.That(files, Has.Some.EndsWith("transforms_train.json").And.Some.EndsWith("cameras.txt").And.Some.EndsWith("rig_preview.ply"));
            foreach (var file in files)
                Assert.That(File.ReadAllBytes(Path.Combine(german, file)), Is.EqualTo(File.ReadAllBytes(Path.Combine(invariant, file))), file);
        }

        string Run(CultureInfo culture, string name)
        {
            var saved = CultureInfo.CurrentCulture;
            CultureInfo.CurrentCulture = culture;
            try
            {
                var settings = new DatasetSettings { Name = "d", Width = SyntheticViews.Width, Height = SyntheticViews.Height, Supersampling = SyntheticViews.K, Distance = 3.3 };
                settings.Train.Count = 3;
                settings.Val.Count = 2;
                settings.Test.Count = 2;
                settings.Test.Depth = ExtraOutput.Png;
                var project = Path.Combine(_root, name);
                var run = DatasetRun.Prepare(settings, new PlanTarget(new Vector3d(0.25, -1.5, 2.75), 0.7), project);
                var session = run.Begin();
                var writer = new ViewFileWriter(run.Plan, session, SyntheticViews.FakeExr);
                foreach (var view in run.Plan.Views) writer.Write(view, SyntheticViews.Colour(), SyntheticViews.Data());
                session.WriteText("settings.json", DatasetSettingsJson.Write(settings));
                session.WriteBytes(DatasetLayout.RigPreviewFileName, stream => RigPreviewPly.Write(run.Plan, stream));
                run.Finish(session, new Provenance(new DateTime(2026, 1, 2, 3, 4, 5, DateTimeKind.Utc), "2022.3.62f1", "unit-test"));
                foreach (var target in new[] { ExportTarget.Nerfstudio, ExportTarget.Colmap, ExportTarget.Ngp })
                    DatasetConverter.Convert(run.DatasetFolder, target);
                return run.DatasetFolder;
            }
            finally
            {
                CultureInfo.CurrentCulture = saved;
            }
        }
    }
}
