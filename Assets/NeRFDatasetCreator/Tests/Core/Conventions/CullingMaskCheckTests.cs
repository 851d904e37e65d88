using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class CullingMaskCheckTests
    {
        static string Name(int layer) => layer == 0 ? "Default" : layer == 8 ? "Props" : "";

        [Test]
        public void EveryLayerDrawnIsFine()
        {
            Assert.That(CullingMaskCheck.Check(~0, new[] { 0, 8, 31 }, Name, "Main Camera", out var isError), Is.Null);
            Assert.That(isError, Is.False);
        }

        [Test]
        public void SomeRenderersOnACulledLayerIsAWarningNamingTheLayer()
        {
            // Mask "Everything but layer 8": two of three renderers stay visible.
            var problem = CullingMaskCheck.Check(~(1 << 8), new[] { 0, 8, 0 }, Name, "Main Camera", out var isError);
            Assert.That(isError, Is.False);
            Assert.That(problem.Field, Is.EqualTo("camera.copyFromCamera"));
            Assert.That(problem.Reason, Does.Contain("'Props' (8)").And.Contain("1 of the target's 3 renderers"));
        }

        [Test]
        public void EveryRendererCulledIsAnError()
        {
            // Mask = layer 0 only; both renderers on layers 8 and 9.
            var problem = CullingMaskCheck.Check(1, new[] { 8, 9 }, Name, "Main Camera", out var isError);
            Assert.That(isError, Is.True);
            Assert.That(problem.Reason, Does.Contain("every image would be empty").And.Contain("'Props' (8), layer (9)"));
        }
    }
}
