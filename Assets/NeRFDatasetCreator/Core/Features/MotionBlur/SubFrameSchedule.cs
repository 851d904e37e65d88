using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>One sub-frame render: its fraction of the shutter interval, camera pose and content time.</summary>
    public readonly struct SubFrame
    {
        public SubFrame(int index, double fraction, UnityPose pose, double? seconds)
        {
            Index = index;
            Fraction = fraction;
            Pose = pose;
            Seconds = seconds;
        }

        public int Index { get; }

        /// <summary>τ = (k + ½)/N, the fraction of the interval (0 = shutter opens, 1 = closes).</summary>
        public double Fraction { get; }

        public UnityPose Pose { get; }

        /// <summary>The content time in seconds (dynamic captures); null in a static capture.</summary>
        public double? Seconds { get; }
    }

    /// <summary>
    /// The sub-frames of one blurred view: N renders at τ_k = (k + ½)/N — the midpoint rule for the box-shaped shutter,
    /// each sub-frame standing for the slice [k/N, (k+1)/N] of the interval — at <see cref="ShutterMotion.At"/>(τ_k) and the
    /// content time <see cref="ShutterMotion.SecondsAt"/>(τ_k). Their average in linear light is the blurred image
    /// (<see cref="SubFrameAccumulator"/>). Error bound (Documentation~/motion-blur.md): for an edge whose image moves
    /// L pixels over the shutter and pixels that are box-filtered (supersampling), the average differs from the exact
    /// integral by at most L/(8N²) of the edge's contrast while L/N ≤ 1 pixel, and by at most 1/(2N) always.
    /// </summary>
    public static class SubFrameSchedule
    {
        public static double Fraction(int k, int count) => (k + 0.5) / count;

        public static IReadOnlyList<SubFrame> For(ShutterMotion motion, int count)
        {
            if (motion == null) throw new ArgumentNullException(nameof(motion));
            if (count < 1) throw new ArgumentOutOfRangeException(nameof(count), count, "at least one sub-frame");
            var frames = new SubFrame[count];
            for (var k = 0; k < count; k++)
            {
                var t = Fraction(k, count);
                frames[k] = new SubFrame(k, t, motion.At(t), motion.SecondsAt(t));
            }
            return frames;
        }

        /// <summary>The bound on |average − integral| for an edge moving <paramref name="pixels"/> over the shutter with <paramref name="count"/> sub-frames, as a fraction of its contrast.</summary>
        public static double ErrorBound(double pixels, int count)
        {
            var perSubFrame = pixels / count;
            var whenFine = pixels / (8.0 * count * count);
            return perSubFrame <= 1 ? Math.Min(whenFine, 0.5 / count) : 0.5 / count;
        }
    }
}
