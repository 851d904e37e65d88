namespace NerfDatasetCreator
{
    /// <summary>
    /// Encodes a float image as an OpenEXR file: <paramref name="channels"/> floats per pixel (1 = depth, 4 = normal
    /// x y z + coverage), rows bottom-up (texture order). Core has no EXR writer; the Unity layer passes
    /// ImageConversion.EncodeArrayToEXR, which is thread-safe. Must be callable from worker threads.
    /// </summary>
    public delegate byte[] ExrEncoder(float[] pixels, int width, int height, int channels);
}
