using System.Diagnostics;
using System.Threading;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The capture's memory bound, without Unity: the main thread rents one view's buffer from an
    /// <see cref="ExactArrayPool{T}"/> per view and queues a job that gives it back when written. However many views,
    /// no more buffers ever exist than the queue's capacity + its workers + the one the producer holds.
    /// </summary>
    [TestFixture]
    public class BoundedMemoryTests
    {
        [TestCase(1, 1)]
        [TestCase(3, 6)]
        [TestCase(8, 2)]
        public void TenThousandViewsNeverNeedMoreBuffersThanQueuedPlusRunningPlusOne(int workers, int capacity)
        {
            const int views = 10000;
            var bound = capacity + workers + 1;
            var pool = new ExactArrayPool<byte>(64, bound);
            var written = 0;
            var clock = Stopwatch.StartNew();
            using (var queue = new BoundedWorkQueue(workers, capacity))
            {
                for (var i = 0; i < views; i++)
                {
                    var buffer = pool.Rent();
                    buffer[0] = (byte)i;
                    queue.Enqueue(() =>
                    {
                        Thread.SpinWait(200); // a little "encoding" work, so the queue fills up
                        Interlocked.Increment(ref written);
                        pool.Return(buffer);
                    });
                }
                queue.WaitForAll();
            }
            TestContext.WriteLine($"{workers} workers, capacity {capacity}: {views} jobs in {clock.Elapsed.TotalMilliseconds:0} ms, {pool.Created} buffers created");
            Assert.That(written, Is.EqualTo(views));
            Assert.That(pool.Created, Is.LessThanOrEqualTo(bound));
        }
    }
}
