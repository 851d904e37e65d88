namespace NerfDatasetCreator
{
    /// <summary>
    /// How the filtered rows are compressed: this project's own Huffman-only DEFLATE (the default), or
    /// System.IO.Compression's DeflateStream at one of its levels (SmallestSize is not in .NET Standard 2.1). The zlib
    /// header's FLEVEL field says which was used; decoders ignore it.
    /// </summary>
    public enum PngCompression
    {
        /// <summary>CompressionLevel.Fastest (zlib level 1): quickest, larger files.</summary>
        Fastest,

        /// <summary>CompressionLevel.Optimal (zlib's default level 6).</summary>
        Optimal,

        /// <summary>CompressionLevel.NoCompression: stored blocks, for debugging or already-noisy data.</summary>
        None,

        /// <summary>
        /// Huffman codes built from this image's own byte counts, runs of bytes equal to the byte a pixel earlier as
        /// matches at the pixel distance, no LZ77 search (<see cref="HuffmanDeflate"/>): about 7× DeflateStream's
        /// level 6 on .NET and 9× on Mono for an RGBA render, with files smaller on masks and 20 % (renders) to 2×
        /// (smooth 16-bit depth) larger than level 6's. Falls back to stored blocks for incompressible data.
        /// </summary>
        Huffman,

        /// <summary>
        /// Huffman codes per block of symbols plus a fast greedy LZ77 search (one candidate per 4-byte hash, matches
        /// across rows up to 32 KiB back; <see cref="Lz77Deflate"/>): files about the size of zlib level 6's at
        /// several times its speed on Mono.
        /// </summary>
        Lz77,
    }
}
