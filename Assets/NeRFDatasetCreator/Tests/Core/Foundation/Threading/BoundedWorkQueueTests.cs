using System;
using System.Collections.Concurrent;
using System.Linq;
using System.Threading;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class BoundedWorkQueueTests
    {
        const int Long = 10000; // ms; only reached when the code under test is broken (a hang), never on success

        [Test]
        public void EveryQueuedJobRunsExactlyOnce()
        {
            var runs = new ConcurrentDictionary<int, int>();
            using (var queue = new BoundedWorkQueue(3, 4))
            {
                for (var i = 0; i < 500; i++)
                {
                    var index = i;
                    queue.Enqueue(() => runs.AddOrUpdate(index, 1, (_, n) => n + 1));
                }
                queue.WaitForAll();
                Assert.That(queue.Completed, Is.EqualTo(500));
            }
            Assert.That(runs.Keys.OrderBy(k => k), Is.EqualTo(Enumerable.Range(0, 500)));
            Assert.That(runs.Values.All(n => n == 1), Is.True);
        }

        [Test]
        public void ProducerCannotQueueMoreThanCapacityWhileWorkersAreBusy()
        {
            using (var gate = new ManualResetEventSlim(false))
            using (var started = new CountdownEvent(2))
            using (var queue = new BoundedWorkQueue(2, 3))
            {
                // Two jobs occupy both workers, then three fill the queue: the sixth does not fit.
                for (var i = 0; i < 2; i++)
                    queue.Enqueue(() => { started.Signal(); gate.Wait(); });
                Assert.That(started.Wait(Long), Is.True, "workers did not start");
                for (var i = 0; i < 3; i++)
                    Assert.That(queue.TryEnqueue(() => gate.Wait(), 0), Is.True, "job " + i + " should fit");
                Assert.That(queue.Pending, Is.EqualTo(3));
                Assert.That(queue.TryEnqueue(() => { }, 0), Is.False);
                gate.Set();
                queue.WaitForAll();
                Assert.That(queue.Completed, Is.EqualTo(5));
            }
        }

        [Test]
        public void AFailingJobStopsTheQueueAndReachesTheProducer()
        {
            var ranAfter = 0;
            using (var queue = new BoundedWorkQueue(1, 8))
            {
                queue.Enqueue(() => throw new System.IO.IOException("disk full"));
                var failure = Assert.Throws<WorkQueueFailedException>(() =>
                {
                    // The failure arrives at the latest after the one worker took the first job.
                    for (var i = 0; i < Long; i++)
                    {
                        queue.Enqueue(() => Interlocked.Increment(ref ranAfter));
                        Thread.Sleep(1);
                    }
                });
                Assert.That(failure.InnerException, Is.TypeOf<System.IO.IOException>());
                Assert.That(failure.Message, Does.Contain("disk full"));
                Assert.Throws<WorkQueueFailedException>(() => queue.WaitForAll());
                Assert.That(queue.Failure.Message, Is.EqualTo("disk full"));
            }
        }

        [Test]
        public void CancelDropsJobsThatHaveNotStarted()
        {
            var ran = 0;
            using (var gate = new ManualResetEventSlim(false))
            using (var started = new ManualResetEventSlim(false))
            using (var queue = new BoundedWorkQueue(1, 10))
            {
                queue.Enqueue(() => { started.Set(); gate.Wait(); Interlocked.Increment(ref ran); });
                Assert.That(started.Wait(Long), Is.True);
                for (var i = 0; i < 5; i++) queue.Enqueue(() => Interlocked.Increment(ref ran));
                queue.Cancel();
                gate.Set();
                queue.WaitForAll();
                Assert.That(queue.IsCancelled, Is.True);
                Assert.Throws<OperationCanceledException>(() => queue.Enqueue(() => { }));
            }
            Assert.That(ran, Is.EqualTo(1), "only the running job finishes");
        }

        [Test]
        public void CancelWakesAProducerBlockedOnAFullQueue()
        {
            using (var gate = new ManualResetEventSlim(false))
            using (var started = new ManualResetEventSlim(false))
            using (var queue = new BoundedWorkQueue(1, 1))
            {
                queue.Enqueue(() => { started.Set(); gate.Wait(); });
                Assert.That(started.Wait(Long), Is.True);
                queue.Enqueue(() => { });
                Exception thrown = null;
                var producer = new Thread(() =>
                {
                    try { queue.Enqueue(() => { }); }
                    catch (Exception e) { thrown = e; }
                });
                producer.Start();
                queue.Cancel();
                Assert.That(producer.Join(Long), Is.True, "the blocked producer never woke up");
                Assert.That(thrown, Is.TypeOf<OperationCanceledException>());
                gate.Set();
            }
        }

        [Test]
        public void NothingCanBeQueuedAfterWaitForAll()
        {
            using (var queue = new BoundedWorkQueue(1, 1))
            {
                queue.WaitForAll();
                Assert.Throws<InvalidOperationException>(() => queue.Enqueue(() => { }));
            }
        }

        [TestCase(0, 1, "workerCount")]
        [TestCase(1, 0, "capacity")]
        public void RejectsOutOfRangeSizesNamingTheParameter(int workers, int capacity, string field)
        {
            var e = Assert.Throws<InvalidParameterException>(() => new BoundedWorkQueue(workers, capacity).Dispose());
            Assert.That(e.Problems.Single().Field, Is.EqualTo(field));
        }
    }
}
