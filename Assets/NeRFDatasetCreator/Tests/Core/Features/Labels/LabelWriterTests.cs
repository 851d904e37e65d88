using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>The writer's id maps from a hand-made id pass, including a table that grows between time steps, and its refusals.</summary>
    [TestFixture]
    public class LabelWriterTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();
        [TearDown] public void Delete() => _temp.Dispose();

        (DatasetRun Run, DatasetWriteSession Session, ViewFileWriter Writer) Begin()
        {
            var settings = new DatasetSettings { Name = "ids", Width = 8, Height = 8, Supersampling = 2 };
            settings.Train.Count = 1;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            settings.Labels = new LabelSettings { Enabled = true, Instances = InstanceRule.Renderer, ClassFrom = ClassSource.Tag };
            var run = DatasetRun.Prepare(settings, new PlanTarget(Vector3d.Zero, 1, 0), _temp.Path);
            Assert.That(run.Problems, Is.Empty);
            var session = run.Begin();
            return (run, session, new ViewFileWriter(run.Plan, session, null));
        }

        /// <summary>A 16×16 frame (8×8 at supersampling 2): left half id <paramref name="left"/>, right half <paramref name="right"/>, colour and mask to match.</summary>
        static RawFrame Frame(ushort left, ushort right)
        {
            var frame = new RawFrame(16, 16, 2) { ColorSrgb = new byte[16 * 16 * 4], Mask = new byte[16 * 16], MaskBytesPerPixel = 1, InstanceIds = new ushort[16 * 16] };
            for (var y = 0; y < 16; y++)
                for (var x = 0; x < 16; x++)
                {
                    var id = x < 8 ? left : right;
                    frame.InstanceIds[y * 16 + x] = id;
                    if (id == 0) continue;
                    frame.Mask[y * 16 + x] = 255;
                    frame.ColorSrgb[(y * 16 + x) * 4 + 3] = 255;
                }
            return frame;
        }

        static SceneObjectInfo Object(string name, int sibling, string tag) =>
            new SceneObjectInfo(new[] { new SceneNode("Target", 0), new SceneNode(name, sibling, tag) }, 1);

        [Test]
        public void ObjectsAddedBetweenTimeStepsAppearInTheNextViewsSemanticMap()
        {
            var (run, session, writer) = Begin();
            var table = LabelTable.Build(run.Plan.Settings.Labels, new[] { Object("Rock", 0, "Stone") });
            writer.Labels = table;
            var views = run.Plan.Views;
            writer.Write(views[0], Frame(1, 0), Frame(1, 0));
            // The next time step spawns a crate (tag Box): id 2, a new class 2.
            Assert.That(table.AddAppearing(new[] { Object("Rock", 0, "Stone"), Object("Crate", 1, "Box") }), Is.EqualTo(1));
            writer.Write(views[1], Frame(1, 2), Frame(1, 2));

            var instance = PngGray16Reader.Read(session.PathOf(DatasetLayout.RelativePath(views[1].Split, views[1].Index, DatasetFileKind.InstancePng)), out var w, out var h);
            var semantic = PngGray16Reader.Read(session.PathOf(DatasetLayout.RelativePath(views[1].Split, views[1].Index, DatasetFileKind.SemanticPng)), out _, out _);
            Assert.That((w, h), Is.EqualTo((8, 8)));
            Assert.That(instance.Take(8), Is.EqualTo(new ushort[] { 1, 1, 1, 1, 2, 2, 2, 2 }));
            Assert.That(semantic.Take(8), Is.EqualTo(new ushort[] { 1, 1, 1, 1, 2, 2, 2, 2 }));
            var first = PngGray16Reader.Read(session.PathOf(DatasetLayout.RelativePath(views[0].Split, views[0].Index, DatasetFileKind.InstancePng)), out _, out _);
            Assert.That(first.Take(8), Is.EqualTo(new ushort[] { 1, 1, 1, 1, 0, 0, 0, 0 }));
            session.DiscardPartialFiles();
        }

        [Test]
        public void AViewWithoutTheIdPassOrARunWithoutATableIsRefusedSayingWhatIsMissing()
        {
            var (run, session, writer) = Begin();
            var view = run.Plan.Views[0];
            var e = Assert.Throws<InvalidOperationException>(() => writer.Write(view, Frame(1, 0), Frame(1, 0)));
            Assert.That(e.Message, Does.Contain("ViewFileWriter.Labels"));
            writer.Labels = LabelTable.Build(run.Plan.Settings.Labels, new[] { Object("Rock", 0, "Stone") });
            var noIds = Frame(1, 0);
            noIds.InstanceIds = null;
            e = Assert.Throws<InvalidOperationException>(() => writer.Write(view, noIds, noIds));
            Assert.That(e.Message, Does.Contain("RawFrame.InstanceIds"));
            var f = Assert.Throws<InvalidOperationException>(() => run.Finish(session, new Provenance(new DateTime(2026, 11, 27, 10, 0, 0, DateTimeKind.Utc))));
            Assert.That(f.Message, Does.Contain("label table"));
            session.DiscardPartialFiles();
        }
    }
}
