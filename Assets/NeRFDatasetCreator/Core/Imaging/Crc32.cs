namespace NerfDatasetCreator
{
    /// <summary>
    /// CRC-32 as PNG chunks use it (ISO 3309 / ITU-T V.42: reflected polynomial 0xEDB88320, initial and final
    /// XOR 0xFFFFFFFF), eight bytes per step with eight 256-entry tables ("slicing-by-8": table k holds the CRC of a
    /// byte followed by k zero bytes, so eight lookups replace eight dependent steps). Hand-written because
    /// System.IO.Hashing is not in .NET Standard 2.1.
    /// </summary>
    public static class Crc32
    {
        static readonly uint[] Table = BuildTable();

        static uint[] BuildTable()
        {
            var table = new uint[8 * 256];
            for (uint n = 0; n < 256; n++)
            {
                uint c = n;
                for (int k = 0; k < 8; k++) c = (c & 1) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
                table[n] = c;
            }
            for (int slice = 1; slice < 8; slice++)
                for (int n = 0; n < 256; n++)
                {
                    uint c = table[(slice - 1) * 256 + n];
                    table[slice * 256 + n] = table[c & 0xFF] ^ (c >> 8);
                }
            return table;
        }

        /// <summary>CRC of <paramref name="count"/> bytes from <paramref name="offset"/>.</summary>
        public static uint Compute(byte[] data, int offset, int count) => Finish(Update(Start, data, offset, count));

        /// <summary>Running register before any byte.</summary>
        public const uint Start = 0xFFFFFFFFu;

        /// <summary>Feeds bytes into a running register (start from <see cref="Start"/>, end with <see cref="Finish"/>).</summary>
        public static uint Update(uint crc, byte[] data, int offset, int count)
        {
            uint[] table = Table;
            int i = offset, end = offset + count;
            for (; i + 8 <= end; i += 8)
            {
                uint low = crc ^ (data[i] | (uint)data[i + 1] << 8 | (uint)data[i + 2] << 16 | (uint)data[i + 3] << 24);
                crc = table[7 * 256 + (low & 0xFF)] ^ table[6 * 256 + ((low >> 8) & 0xFF)]
                    ^ table[5 * 256 + ((low >> 16) & 0xFF)] ^ table[4 * 256 + (low >> 24)]
                    ^ table[3 * 256 + data[i + 4]] ^ table[2 * 256 + data[i + 5]]
                    ^ table[256 + data[i + 6]] ^ table[data[i + 7]];
            }
            for (; i < end; i++) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
            return crc;
        }

        public static uint Finish(uint crc) => crc ^ 0xFFFFFFFFu;
    }
}
