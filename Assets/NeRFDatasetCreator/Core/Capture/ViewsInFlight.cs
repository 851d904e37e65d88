using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How many views a capture keeps alive at once, bounded by memory (issue 32, R4-10). A view's readback arrays live
    /// from its readback until its writer is done: the views in the readback ring, those queued for a writer and those
    /// being written. Counted by views alone, a lens capture — whose passes are rendered at k× the wide size, ~0.43 GB per
    /// 1080p view at k = 2 with normals and labels — held up to 27 of them (~12 GB). <see cref="For"/> lowers the queue,
    /// then the writers, then the readbacks until the views alive fit the budget (never below one of each: a view too
    /// large for the budget is still captured, three at a time).
    /// </summary>
    public struct ViewsInFlight
    {
        /// <summary>The share of the machine's memory the capture's views may hold (the Editor, the scene and the GPU driver keep the rest).</summary>
        public const double MemoryShare = 0.25;

        /// <summary>The least budget, whatever the machine reports: 1 GiB.</summary>
        public const long MinimumBudgetBytes = 1L << 30;

        /// <summary>Views in the readback ring (rendered, being read back).</summary>
        public int Readbacks;

        /// <summary>Writer threads, each writing one view.</summary>
        public int Writers;

        /// <summary>Views read back and waiting for a writer.</summary>
        public int Queue;

        /// <summary>The most views alive at once: <see cref="Readbacks"/> + <see cref="Queue"/> + <see cref="Writers"/>.</summary>
        public int Total => Readbacks + Queue + Writers;

        /// <summary>The budget for a machine with <paramref name="systemMemoryBytes"/> of memory: <see cref="MemoryShare"/> of it, at least <see cref="MinimumBudgetBytes"/>.</summary>
        public static long BudgetFor(long systemMemoryBytes) => Math.Max(MinimumBudgetBytes, (long)(systemMemoryBytes * MemoryShare));

        /// <summary>
        /// The CPU arrays one view holds (CapturedView): the colour pair as RGBA halves (8 bytes a sample each), the
        /// averaged pair too with motion blur, the mask (1 byte a sample) and labels (4) at the colour's size, depth (4
        /// bytes a pixel) and normals (16) at the data size.
        /// </summary>
        public static long ViewBytes(int colourWidth, int colourHeight, int dataWidth, int dataHeight, bool colour, bool blurred,
            bool mask, bool labels, bool depth, bool normals)
        {
            long samples = (long)colourWidth * colourHeight, data = (long)dataWidth * dataHeight;
            long bytes = 0;
            if (colour) bytes += 2 * 8 * samples;
            if (colour && blurred) bytes += 2 * 8 * samples;
            if (mask) bytes += samples;
            if (labels) bytes += 4 * samples;
            if (depth) bytes += 4 * data;
            if (normals) bytes += 16 * data;
            return bytes;
        }

        /// <summary>
        /// The views in flight for views of <paramref name="viewBytes"/> each within <paramref name="budgetBytes"/>, starting
        /// from the capture's own choice (<paramref name="readbacks"/>, <paramref name="writers"/>, <paramref name="queue"/>):
        /// unchanged when it fits; otherwise the queue shrinks first (it only smooths the writers' pace), then the writers,
        /// then the readbacks, each to at least 1.
        /// </summary>
        public static ViewsInFlight For(long viewBytes, long budgetBytes, int readbacks, int writers, int queue)
        {
            if (viewBytes < 0) throw new ArgumentOutOfRangeException(nameof(viewBytes), viewBytes, "a view holds no negative bytes");
            if (readbacks < 1 || writers < 1 || queue < 1) throw new ArgumentOutOfRangeException(nameof(readbacks), "at least one readback, writer and queue place");
            var fits = viewBytes == 0 ? int.MaxValue : (int)Math.Min(int.MaxValue, Math.Max(0, budgetBytes) / viewBytes);
            var limit = new ViewsInFlight { Readbacks = readbacks, Writers = writers, Queue = queue };
            while (limit.Total > fits)
            {
                if (limit.Queue > 1) limit.Queue--;
                else if (limit.Writers > 1) limit.Writers--;
                else if (limit.Readbacks > 1) limit.Readbacks--;
                else break;
            }
            return limit;
        }
    }
}
