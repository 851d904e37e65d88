using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Review R4-6, Core's half: the per-step geometry pack reads each step's meshes on the calling thread (Unity's main
    /// thread) and packs, writes and hashes them on a worker, one step in flight; it reports its progress; a worker's
    /// failure comes back as the exception it was; and the preflight's calibration never computes every step.
    /// </summary>
    public class GeometryPackWriterPipelineTests
    {
        const int Steps = 4;

        static DatasetRun Run(string project)
        {
            var s = new DatasetSettings { Name = "pipeline", Width = 32, Height = 24, Supersampling = 1, Distance = 4, GeometryPackEveryStep = true };
            s.Train.Count = 2;
            s.Val.Count = 1;
            s.Test.Count = 1;
            s.Time.Mode = TimeMode.MultiView;
            s.Time.Steps = Steps;
            s.Time.StartSeconds = 0;
            s.Time.EndSeconds = 1;
            var run = DatasetRun.Prepare(s, new PlanTarget(Vector3d.Zero, 0.5, 1), project);
            Assert.That(run.Problems, Is.Empty);
            return run;
        }

        [Test]
        public void StepsAreReadOnTheCallingThreadWrittenByAWorkerAndReported()
        {
            using (var temp = new TempFolder())
            {
                var run = Run(temp.Path);
                var session = run.Begin();
                var caller = Thread.CurrentThread.ManagedThreadId;
                var readOn = new List<int>();
                var progress = new List<string>();
                var record = GeometryPackWriter.Write(session, run.Plan, null, k =>
                {
                    readOn.Add(Thread.CurrentThread.ManagedThreadId);
                    return AnalyticSceneMeshes.At(run.Plan.Time.NormalisedOf(k));
                }, (done, total) => progress.Add(done + "/" + total));
                Assert.That(readOn, Is.EqualTo(Enumerable.Repeat(caller, Steps)), "Unity's meshes are read on the calling (main) thread only");
                Assert.That(progress, Is.EqualTo(new[] { "0/4", "1/4", "2/4", "3/4", "4/4" }));
                var steps = (Newtonsoft.Json.Linq.JArray)record["steps"];
                Assert.That(steps.Count, Is.EqualTo(Steps));
                for (var k = 0; k < Steps; k++)
                {
                    var file = session.PathOf(GeometryPackSteps.RelativePath(k));
                    Assert.That(PointCloudRecord.HashOf(file), Is.EqualTo((string)steps[k]["sha256"]), "step " + k + " written whole before Write returned");
                    Assert.That((long)steps[k]["triangles"], Is.EqualTo(AnalyticSceneMeshes.At(0).Sum(m => (long)m.TriangleCount)));
                }
            }
        }

        [Test]
        public void AWorkersFailureComesBackAsItWasAndNoWorkerIsLeftWriting()
        {
            using (var temp = new TempFolder())
            {
                var run = Run(temp.Path);
                var session = run.Begin();
                // A folder where step 1's file must go: the worker's write of step 1 fails with the file system's own error.
                Directory.CreateDirectory(session.PathOf(GeometryPackSteps.RelativePath(1)));
                var reads = 0;
                var error = Assert.Catch<Exception>(() => GeometryPackWriter.Write(session, run.Plan, null, k =>
                {
                    reads++;
                    return AnalyticSceneMeshes.At(0);
                }));
                Assert.That(error, Is.Not.InstanceOf<AggregateException>(), "unwrapped");
                Assert.That(error, Is.InstanceOf<IOException>().Or.InstanceOf<UnauthorizedAccessException>());
                Assert.That(reads, Is.LessThanOrEqualTo(3), "reading stops at most one step after the failed write");
                Assert.That(File.Exists(session.PathOf(GeometryPackSteps.RelativePath(3))), Is.False, "no step after the failure is written");
            }
        }

        [Test]
        public void ThePreflightsCalibrationWritesTheStartMeshOnly()
        {
            var s = new DatasetSettings { Width = 800, Height = 600, GeometryPackEveryStep = true };
            var calibration = PreflightCheck.CalibrationSettings(s, "/tmp/calibration", "calibration");
            Assert.That(calibration.GeometryPack, Is.True, "the start mesh is still checked");
            Assert.That(calibration.GeometryPackEveryStep, Is.False);
            Assert.That(s.GeometryPackEveryStep, Is.True, "the capture's own settings are untouched");
        }
    }
}
