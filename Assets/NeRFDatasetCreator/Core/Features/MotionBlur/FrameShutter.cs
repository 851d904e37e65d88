namespace NerfDatasetCreator
{
    /// <summary>A frame's motion-blur keys as read (<see cref="MotionBlurKeys.Read"/>); every value null when absent.</summary>
    public sealed class FrameShutter
    {
        /// <summary>Whether the frame has <c>transform_matrix_start</c> / <c>_end</c> (of any form).</summary>
        public bool HasStart { get; internal set; }
        public bool HasEnd { get; internal set; }

        /// <summary>The start / end pose when it is 4 rows of 4 numbers, as written (NaN kept, not checked for rigidity), else null.</summary>
        public Matrix4x4d? Start { get; internal set; }
        public Matrix4x4d? End { get; internal set; }

        /// <summary>instant-ngp's <c>rolling_shutter</c> [A, B, C, D] of the frame, else of its file (three or four finite numbers, D = 0 when three), or null.</summary>
        public double[] RollingShutter { get; internal set; }

        /// <summary>Why the <c>rolling_shutter</c> that applies to the frame is malformed (<see cref="MotionBlurKeys.RollingShutterProblem"/>), or null.</summary>
        public string RollingShutterProblem { get; internal set; }

        /// <summary>A frame without motion-blur keys.</summary>
        public static readonly FrameShutter None = new FrameShutter();
    }
}
