namespace NerfDatasetCreator
{
    /// <summary>One pixel's surface point at both times and its flow (<see cref="SurfaceFlow.At"/>).</summary>
    public struct FlowSample
    {
        /// <summary>The surface point at t.</summary>
        public double Px, Py, Pz;
        /// <summary>The same point at t′.</summary>
        public double Qx, Qy, Qz;
        /// <summary>Flow in pixels (x right, y down); NaN when the point is behind the camera at t′.</summary>
        public double Dx, Dy;
        public int Triangle;
    }
}
