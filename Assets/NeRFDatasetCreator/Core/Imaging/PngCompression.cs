namespace NerfDatasetCreator
{
    /// <summary>
    /// DEFLATE effort, mapped onto System.IO.Compression.CompressionLevel (SmallestSize is not in .NET Standard 2.1).
    /// The zlib header's FLEVEL field says which was used; decoders ignore it.
    /// </summary>
    public enum PngCompression
    {
        /// <summary>CompressionLevel.Fastest (zlib level 1): quickest, larger files.</summary>
        Fastest,

        /// <summary>CompressionLevel.Optimal (zlib's default level 6).</summary>
        Optimal,

        /// <summary>CompressionLevel.NoCompression: stored blocks, for debugging or already-noisy data.</summary>
        None,
    }
}
