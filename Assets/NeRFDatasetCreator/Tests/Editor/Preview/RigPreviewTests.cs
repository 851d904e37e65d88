using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>The preview's state without a Scene view: colours from Core, plan changes, visibility, selection.</summary>
    [TestFixture]
    public class RigPreviewTests
    {
        [Test]
        public void TheLegendColoursAreCoresSplitColours()
        {
            Assert.That(RigPreview.TrainColor.r, Is.EqualTo(SplitColors.Train.R));
            Assert.That(RigPreview.ValColor.g, Is.EqualTo(SplitColors.Val.G));
            Assert.That(RigPreview.TestColor.b, Is.EqualTo(SplitColors.Test.B));
            Assert.That(RigPreview.ColorOf(PreviewSplit.Val).r, Is.EqualTo(SplitColors.Val.R));
        }

        [Test]
        public void HidingASplitIsRememberedAndNothingIsSelectedAfterANewPlan()
        {
            using (var preview = new RigPreview())
            {
                var train = CameraRig.Place(new HaloFormation(), 8, Vector3d.Zero, 4);
                var test = CameraRig.Place(new OrbitFormation(), 20, Vector3d.Zero, 4);
                preview.SetPlan(train, null, test, 40, 1, Vector3d.Zero, new Vector3d(1, 1, 1), 4);

                Assert.That(preview.Selected, Is.Null);
                Assert.That(preview.IsVisible(PreviewSplit.Test), Is.True);
                preview.SetVisible(PreviewSplit.Test, false);
                Assert.That(preview.IsVisible(PreviewSplit.Test), Is.False);
                Assert.That(preview.IsVisible(PreviewSplit.Train), Is.True);
            }
        }

        [Test]
        public void AnInvalidFieldOfViewClearsThePreviewInsteadOfThrowing()
        {
            using (var preview = new RigPreview())
            {
                var train = CameraRig.Place(new HaloFormation(), 4, Vector3d.Zero, 4);
                Assert.That(() => preview.SetPlan(train, null, null, 0, 1, Vector3d.Zero, Vector3d.Zero, 4), Throws.Nothing);
                Assert.That(preview.Selected, Is.Null);
            }
        }
    
        [Test]
        public void AVolumesBoxMatrixTakesTheUnitCubeOntoCoresBox()
        {
            var box = new OrientedBox("Volume", new Vector3d(1, 2, 3), Quaterniond.AngleAxis(30, new Vector3d(0, 1, 0)), new Vector3d(4, 2, 6));
            var m = RigPreview.BoxMatrix(box);
            for (var i = 0; i < 8; i++)
            {
                var local = new Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5);
                var drawn = m.MultiplyPoint3x4(new Vector3((float)local.X, (float)local.Y, (float)local.Z));
                var expected = box.PointAt(local);
                Assert.That(new double[] { drawn.x, drawn.y, drawn.z }, Is.EqualTo(new[] { expected.X, expected.Y, expected.Z }).Within(1e-5), "corner " + i);
            }
        }

        [Test]
        public void APlanWithVolumesIsShownWithoutThrowing()
        {
            using (var preview = new RigPreview())
            {
                var train = CameraRig.Place(new HaloFormation(), 4, Vector3d.Zero, 4);
                var volumes = new List<KeyValuePair<DatasetSplit, OrientedBox>>
                {
                    new KeyValuePair<DatasetSplit, OrientedBox>(DatasetSplit.Train, OrientedBox.AxisAligned("Room", Vector3d.Zero, new Vector3d(10, 3, 10))),
                };
                Assert.That(() => preview.SetPlan(train, null, null, 40, 1, Vector3d.Zero, new Vector3d(1, 1, 1), 0, volumes), Throws.Nothing);
                Assert.That(() => preview.ClearPlan(), Throws.Nothing);
            }
        }
    }
}
