namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Turns one captured view into files: post-processing (downsample, straight alpha, row flip), encoding and
    /// writing. Called on worker threads, several views at once: implementations must be thread-safe and must not
    /// call Unity APIs other than the thread-safe ImageConversion.EncodeArrayTo* / EncodeNativeArrayTo*. Throw on
    /// failure (disk full, access denied): the capture stops and reports it.
    /// </summary>
    public interface IViewWriter
    {
        void Write(CapturedView view);
    }
}
