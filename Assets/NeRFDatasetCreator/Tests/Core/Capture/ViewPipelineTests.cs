using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <see cref="ViewPipeline"/>'s lens stage with a data frame of its own at the colour frame's size: it must not be
    /// resampled into the thread's reused arrays the colour frame's passes were just resampled into (the capture's data
    /// frame is at the output size, another size; this pins the rule for one that is not).
    /// </summary>
    [TestFixture]
    public class ViewPipelineTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        /// <summary>The colour image of each view through a lens, its depth and normals from the colour frame or from a frame of their own whose colour and mask are empty.</summary>
        static List<byte[]> Images(string project, string name, bool dataApart)
        {
            var settings = new DatasetSettings { Name = name, Width = 32, Height = 24, Supersampling = 2, Distance = 1.8,
                Lens = new LensSettings { Model = "opencv", K1 = -0.12, K2 = 0.02 } };
            settings.Camera.VerticalFovDegrees = 70;
            foreach (var split in new[] { settings.Train, settings.Val, settings.Test })
            {
                split.Count = 2;
                split.Depth = ExtraOutput.Png;
                split.Mask = true;
            }
            var run = DatasetRun.Prepare(settings, new PlanTarget(AnalyticDataset.Centre, 1.2), project);
            Assert.That(run.Problems, Is.Empty, "the test's settings");
            var session = run.Begin();
            var pipeline = new ViewPipeline(run.Plan, session, null, null);
            var wide = pipeline.WideRender;
            Assert.That(wide, Is.Not.Null, "a lens capture renders wide");
            var scene = AnalyticScene.Layout(run.Plan.Normalisation, AnalyticDataset.Centre);
            var images = new List<byte[]>();
            foreach (var view in run.Plan.Views)
            {
                var frame = AnalyticDataset.Render(scene, AnalyticDataset.Pinhole(view.TransformMatrix, wide), wide.Width, wide.Height,
                    new AnalyticDataset.Options(), run.Plan.Normalisation.Scale, settings.Supersampling);
                var data = !dataApart ? frame : new RawFrame(frame.Width, frame.Height, frame.Supersampling)
                {
                    ColorOverBlack = new ushort[frame.ColorOverBlack.Length], ColorOverWhite = new ushort[frame.ColorOverWhite.Length],
                    Mask = new byte[frame.Mask.Length], MaskBytesPerPixel = 1, Depth = frame.Depth, Normals = frame.Normals,
                };
                pipeline.Write(view, frame, data);
                images.Add(File.ReadAllBytes(session.PathOf(DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.Color))));
                images.Add(File.ReadAllBytes(session.PathOf(DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.MaskPng))));
                images.Add(File.ReadAllBytes(session.PathOf(DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.DepthPng))));
            }
            session.End();
            return images;
        }

        [Test]
        public void ADataFrameOfItsOwnAtTheColoursSizeLeavesTheColourAndMaskAlone()
        {
            var shared = Images(_temp.Path, "shared", false);
            var apart = Images(_temp.Path, "apart", true);
            Assert.That(apart.Count, Is.EqualTo(shared.Count));
            for (var i = 0; i < shared.Count; i++) Assert.That(apart[i], Is.EqualTo(shared[i]), "file " + i);
        }
    }
}
