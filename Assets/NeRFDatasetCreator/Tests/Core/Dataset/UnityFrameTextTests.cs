using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    public class UnityFrameTextTests
    {
        [Test]
        public void TheTargetPathIsTheSceneAColonAndTheHierarchyFromTheRoot()
        {
            Assert.That(UnityFrameText.TargetPath("Assets/Scenes/Lego.unity", new[] { "Root", "Lego" }), Is.EqualTo("Assets/Scenes/Lego.unity:/Root/Lego"));
            Assert.That(UnityFrameText.TargetPath("", new[] { "Lego" }), Is.EqualTo(":/Lego"), "a scene never saved has no path");
            Assert.That(UnityFrameText.TargetPath(null, new[] { "A", "B", "C" }), Is.EqualTo(":/A/B/C"));
            Assert.Throws<ArgumentException>(() => UnityFrameText.TargetPath("s.unity", new string[0]));
        }

        [Test]
        public void AGlobalObjectIdIsKeptOnlyWhereItIdentifiesSomething()
        {
            const string saved = "GlobalObjectId_V1-2-4d9e3c1a2b0f4e5d8c7b6a5f4e3d2c1b-1234567890-0";
            Assert.That(UnityFrameText.GlobalObjectIdOrNull(saved), Is.EqualTo(saved));
            Assert.That(UnityFrameText.GlobalObjectIdOrNull("GlobalObjectId_V1-2-00000000000000000000000000000000-1234567890-0"), Is.Null, "unsaved scene: no asset GUID");
            Assert.That(UnityFrameText.GlobalObjectIdOrNull("GlobalObjectId_V1-0-00000000000000000000000000000000-0-0"), Is.Null, "the null id");
            Assert.That(UnityFrameText.GlobalObjectIdOrNull("GlobalObjectId_V1-0-4d9e3c1a2b0f4e5d8c7b6a5f4e3d2c1b-0-0"), Is.Null, "type 0 is the null type");
            Assert.That(UnityFrameText.GlobalObjectIdOrNull(null), Is.Null);
            Assert.That(UnityFrameText.GlobalObjectIdOrNull("not an id"), Is.Null);
        }

        [Test]
        public void AMatrixIsWrittenRowByRow()
        {
            // element(r, c) = 10·r + c: row-major order reads 0, 1, 2, 3, 10, 11, …; column-major would read 0, 10, 20, 30, 1, ….
            var m = UnityFrameText.RowMajor((r, c) => 10 * r + c);
            Assert.That(m, Is.EqualTo(new double[] { 0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23, 30, 31, 32, 33 }));
            // And it is what UnityFrameFacts accepts.
            Assert.That(new UnityFrameFacts(null, null, m, "Linear").TargetLocalToWorld[4], Is.EqualTo(10));
        }
    }
}
