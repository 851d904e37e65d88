using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The views a capture keeps alive at once, bounded by memory (Core <see cref="ViewsInFlight"/>; issue 32, R4-10):
    /// the bytes of one view's readback arrays from the options, against a quarter of the machine's memory as Unity
    /// reports it — <c>SystemInfo.systemMemorySize</c>, "Amount of system memory present", in MB (UnityCsReference
    /// Runtime/Export/SystemInfo/SystemInfo.bindings.cs:105-109 at 2022.3.76f1, :116-120 at 6000.0.78f1). A lens capture,
    /// whose passes are rendered at k× the wide size, then runs with fewer writers and a shorter queue instead of holding
    /// ~12 GB; an ordinary capture is unchanged unless its views are as large.
    /// </summary>
    public static class CaptureMemory
    {
        /// <summary>The in-flight limits for <paramref name="options"/> with <paramref name="writers"/> writer threads wanted.</summary>
        public static ViewsInFlight Bound(CaptureOptions options, int writers)
        {
            var passes = options.EffectivePasses;
            var bytes = ViewsInFlight.ViewBytes(options.SupersampledWidth, options.SupersampledHeight, options.DataWidth, options.DataHeight,
                colour: (passes & CapturePasses.Color) != 0, blurred: options.SubFramesOf != null,
                mask: (passes & CapturePasses.Mask) != 0, labels: (passes & CapturePasses.Labels) != 0,
                depth: (passes & CapturePasses.Depth) != 0, normals: (passes & CapturePasses.Normal) != 0);
            var budget = ViewsInFlight.BudgetFor(SystemInfo.systemMemorySize * (1L << 20));
            return ViewsInFlight.For(bytes, budget, options.ReadbacksInFlight, writers, 2 * writers);
        }
    }
}
