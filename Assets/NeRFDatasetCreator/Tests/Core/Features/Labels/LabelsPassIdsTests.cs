using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The labels pass's readback as ids (<see cref="LabelsPassIds"/>, moved from the Editor's writer): 4 bytes a sample,
    /// the instance id's low byte then its high byte, the class id's two bytes ignored; into the thread's reused buffer.
    /// </summary>
    [TestFixture]
    public class LabelsPassIdsTests
    {
        [Test]
        public void EachSampleIsItsInstanceIdFromTheLowAndTheHighByte()
        {
            var labels = new byte[] { 0, 0, 0, 0, 1, 0, 7, 0, 0x34, 0x12, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0 };
            Assert.That(LabelsPassIds.InstanceIds(labels), Is.EqualTo(new ushort[] { 0, 1, 0x1234, 0xFFFF }));
        }

        [Test]
        public void TheThreadsBufferIsReusedWhileTheSizeStays()
        {
            var first = LabelsPassIds.InstanceIds(new byte[8]);
            var second = LabelsPassIds.InstanceIds(new byte[] { 5, 0, 9, 9, 6, 1, 9, 9 });
            Assert.That(second, Is.SameAs(first));
            Assert.That(second, Is.EqualTo(new ushort[] { 5, 0x0106 }));
            var larger = LabelsPassIds.InstanceIds(new byte[12]);
            Assert.That(larger, Is.Not.SameAs(first));
            Assert.That(larger, Is.EqualTo(new ushort[3]));
        }
    }
}
