namespace NerfDatasetCreator
{
    /// <summary>
    /// Adler-32 (RFC 1950 §8), the checksum of the uncompressed data that ends a zlib stream. DeflateStream writes
    /// raw DEFLATE only, so the zlib framing and this checksum are ours.
    /// </summary>
    public static class Adler32
    {
        const uint Modulus = 65521;

        // The largest n for which 255·n·(n+1)/2 + (n+1)·(Modulus−1) still fits in 32 bits (RFC 1950's NMAX), so the
        // expensive modulo runs once per block instead of once per byte.
        const int BlockLength = 5552;

        public const uint Start = 1;

        public static uint Compute(byte[] data, int offset, int count) => Update(Start, data, offset, count);

        /// <summary>Feeds bytes into a running checksum (start from <see cref="Start"/>).</summary>
        public static uint Update(uint adler, byte[] data, int offset, int count)
        {
            uint s1 = adler & 0xFFFF, s2 = adler >> 16;
            int i = offset, end = offset + count;
            while (i < end)
            {
                int blockEnd = end - i > BlockLength ? i + BlockLength : end;
                for (; i < blockEnd; i++)
                {
                    s1 += data[i];
                    s2 += s1;
                }
                s1 %= Modulus;
                s2 %= Modulus;
            }
            return (s2 << 16) | s1;
        }
    }
}
