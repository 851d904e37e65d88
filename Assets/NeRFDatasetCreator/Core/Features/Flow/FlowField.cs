namespace NerfDatasetCreator
{
    /// <summary>Per-pixel flow of one image: (Δx, Δy) pixels, scene flow (output units), <see cref="FlowState"/>; NaN where no surface.</summary>
    public sealed class FlowField
    {
        public FlowField(int width, int height)
        {
            Width = width;
            Height = height;
            Flow = new float[width * height * 2];
            SceneFlow = new float[width * height * 3];
            State = new byte[width * height];
        }

        public int Width { get; }
        public int Height { get; }
        public float[] Flow { get; }
        public float[] SceneFlow { get; }
        public byte[] State { get; }
    }
}
