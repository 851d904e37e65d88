namespace NerfDatasetCreator
{
    /// <summary>
    /// When a planned view is captured. <see cref="Normalised"/> is the <c>time</c> key D-NeRF, 4DGaussians and
    /// nerfstudio's dnerf parser read, in [0, 1]; <see cref="Seconds"/> is the content time the capture evaluates,
    /// written as <c>time_seconds</c>.
    /// </summary>
    public readonly struct ViewTime
    {
        public ViewTime(double normalised, double seconds, int step, int camera)
        {
            Normalised = normalised;
            Seconds = seconds;
            Step = step;
            Camera = camera;
        }

        /// <summary>(seconds − start) / (end − start), in [0, 1].</summary>
        public double Normalised { get; }

        /// <summary>The content time in seconds.</summary>
        public double Seconds { get; }

        /// <summary>The time step k (times start + k·Δ); −1 for a monocular val/test view between two steps.</summary>
        public int Step { get; }

        /// <summary>Multi-view: the camera of the split's formation (its index in a static capture); −1 in monocular captures.</summary>
        public int Camera { get; }
    }
}
