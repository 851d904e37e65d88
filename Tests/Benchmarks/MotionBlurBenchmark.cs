using System;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Motion blur's CPU cost per view (issue 32, R4-2): one 800×800 view at supersampling 2 (1600×1600 samples) with 16
    /// sub-frames, a global shutter, Linear colour space — the sum of the sub-frames' colour pairs and the averaged pair,
    /// with the allocations of one view. Run with <c>--only blur</c> (run-all <c>--sections blur</c>).
    /// </summary>
    static class MotionBlurBenchmark
    {
        const int Size = 800, K = 2, SubFrames = 16;

        public static void Run(Action<string, double> record, Func<(string Name, Action Run)[], double[]> time)
        {
            var (colour, _) = SyntheticFrame.CaptureLayout(Size, K);
            int w = Size * K, length = w * w * 4;
            ushort[] black = colour.ColorOverBlack, white = colour.ColorOverWhite;
            var readBlack = new ushort[length];
            var readWhite = new ushort[length];
            Console.WriteLine($"Motion blur, one {Size}×{Size} view at supersampling {K} ({w}×{w} samples), {SubFrames} sub-frames; ms CPU and MB allocated per view:");
            Action perView = () =>
            {
                // What the capture did before issue 32, on the main thread: a new accumulator and new outputs per view.
                var accumulator = ViewPipeline.SubFrameAverage(w, w, SubFrames, 0, false);
                for (var k = 0; k < SubFrames; k++) accumulator.Add(k, black, white);
                accumulator.Finish(new ushort[length], new ushort[length]);
            };
            Action copies = () =>
            {
                // The readback copies alone (what the main thread must do per sub-frame whatever the sum costs).
                for (var k = 0; k < SubFrames; k++)
                {
                    Buffer.BlockCopy(black, 0, readBlack, 0, length * 2);
                    Buffer.BlockCopy(white, 0, readWhite, 0, length * 2);
                }
            };
            var outBlack = new ushort[length];
            var outWhite = new ushort[length];
            using (var inline = new BackgroundSubFrameSum(w, w, 0, false, background: false))
            using (var worker = new BackgroundSubFrameSum(w, w, 0, false))
            {
                // The capture since issue 32: one sum per run; the render thread copies each readback into a free input pair.
                Action<BackgroundSubFrameSum> view = sum =>
                {
                    sum.Begin(SubFrames);
                    for (var k = 0; k < SubFrames; k++)
                    {
                        var input = sum.TakeInput(out var b, out var wh);
                        Buffer.BlockCopy(black, 0, b, 0, length * 2);
                        Buffer.BlockCopy(white, 0, wh, 0, length * 2);
                        sum.Add(input, k);
                    }
                    sum.Finish(outBlack, outWhite);
                    sum.WaitIdle();
                };
                var steps = new (string Name, Action Run)[]
                {
                    ("before: new accumulator per view, on the calling thread", perView),
                    ("the sub-frames' readback copies alone (2 × 20 MB each)", copies),
                    ("now: one sum per run, copies + sum on one thread", () => view(inline)),
                    ("now: the same with the sum on its worker thread", () => view(worker)),
                };
                var ms = time(steps);
                record("blur.perview.ms", ms[0]);
                record("blur.copies.ms", ms[1]);
                record("blur.reused.ms", ms[2]);
                record("blur.worker.ms", ms[3]);
                var mb = Allocated(perView);
                var reusedMb = Allocated(() => view(inline));
                var callerMb = Allocated(() => view(worker));
                Console.WriteLine($"  allocated per view: before {mb:F1} MB; now {reusedMb:F3} MB with the sum on the calling thread, {callerMb:F3} MB on the render thread with the worker");
                record("blur.perview.mb", mb);
                record("blur.reused.mb", reusedMb);
                record("blur.worker.caller.mb", callerMb);
            }
            Console.WriteLine();
        }

        /// <summary>MB allocated on this thread by one run.</summary>
        static double Allocated(Action run)
        {
            var before = GC.GetAllocatedBytesForCurrentThread();
            run();
            return (GC.GetAllocatedBytesForCurrentThread() - before) / 1e6;
        }
    }
}
