using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Raw DEFLATE (RFC 1951) with a fast greedy LZ77 search, for PNG's filtered rows: at each position the 4 bytes
    /// there are hashed, the one earlier position with the same hash is the only candidate (no chains, no lazy
    /// evaluation), and a match of at least 4 bytes is taken and extended up to 258. Matches reach 32 768 bytes back,
    /// so across rows too: the row above in an Up- or Sub-filtered smooth area, the repeated residual patterns of a
    /// gradient, the transparent background. The symbols of every <see cref="BlockSymbols"/> go into one
    /// dynamic-Huffman block whose codes come from that block's own counts (a render's background and its object
    /// get their own tables), or into stored blocks when those are smaller (noise).
    /// <para>
    /// The loops keep everything in locals and call nothing per byte, because Mono inlines little. Not thread-safe:
    /// one instance per thread.
    /// </para>
    /// </summary>
    internal sealed class Lz77Deflate
    {
        /// <summary>Symbols (literals and matches) per block: tables adapt to the image's parts at ~100 bytes a block.</summary>
        internal const int BlockSymbols = 1 << 15;

        internal const int Window = 32768;
        internal const int MinMatch = 4;
        internal const int MaxMatch = 258;
        const int HashBits = 15;
        const int LiteralLengthSymbols = 286;
        const int DistanceSymbols = 30;
        const int EndOfBlock = 256;
        const int MaxStoredBlock = 65535;
        const int NoPosition = -0x40000000; // so far back that every distance check fails

        // RFC 1951 §3.2.5: the distance code of every distance 1…32 768, and each code's extra bits and base.
        static readonly byte[] DistanceCodeOf = new byte[Window + 1];
        static readonly byte[] DistanceExtraBits = new byte[DistanceSymbols];
        static readonly int[] DistanceBase = new int[DistanceSymbols];

        static Lz77Deflate()
        {
            for (int code = 0; code < DistanceSymbols; code++)
            {
                int extra = code < 4 ? 0 : code / 2 - 1;
                int first = code < 4 ? code + 1 : (1 << (extra + 1)) + 1 + ((code & 1) << extra);
                DistanceExtraBits[code] = (byte)extra;
                DistanceBase[code] = first;
                for (int d = first; d < first + (1 << extra) && d <= Window; d++) DistanceCodeOf[d] = (byte)code;
            }
        }

        readonly int[] _head = new int[1 << HashBits];
        readonly int[] _symbols = new int[BlockSymbols]; // a literal byte, or length << 16 | distance
        readonly int[] _literalCounts = new int[LiteralLengthSymbols];
        readonly int[] _distanceCounts = new int[DistanceSymbols];
        readonly byte[] _literalLengths = new byte[LiteralLengthSymbols];
        readonly byte[] _distanceLengths = new byte[DistanceSymbols];
        readonly int[] _literalCodes = new int[LiteralLengthSymbols];
        readonly int[] _distanceCodes = new int[DistanceSymbols];
        readonly int[] _lengthEntry = new int[MaxMatch + 1]; // code and extra bits | total bits << 24
        readonly int[] _distanceEntry = new int[DistanceSymbols]; // code | length << 16
        readonly int[] _literalEntry = new int[256]; // code | length << 16
        readonly HuffmanDeflate.CodeLengthHeader _header = new HuffmanDeflate.CodeLengthHeader();

        byte[] _output = new byte[0];
        int _o;
        ulong _bits;
        int _count;

        /// <summary>
        /// Compresses <paramref name="data"/>[0…length) into one DEFLATE stream; the result is
        /// <see cref="Output"/>[0…returned length).
        /// </summary>
        internal int Compress(byte[] data, int length)
        {
            int[] head = _head;
            for (int h = 0; h < head.Length; h++) head[h] = NoPosition;
            int[] symbols = _symbols;
            int[] literalCounts = _literalCounts, distanceCounts = _distanceCounts;
            Array.Clear(literalCounts, 0, literalCounts.Length);
            Array.Clear(distanceCounts, 0, distanceCounts.Length);
            short[] lengthSymbolOf = HuffmanDeflate.LengthSymbolOf;
            byte[] distanceCodeOf = DistanceCodeOf;
            _o = 0;
            _bits = 0;
            _count = 0;
            EnsureOutput(64);

            int n = 0, blockStart = 0, i = 0, last = length - MinMatch;
            uint current = last >= 0 ? data[0] | (uint)data[1] << 8 | (uint)data[2] << 16 | (uint)data[3] << 24 : 0;
            while (i <= last)
            {
                int hash = (int)((current * 2654435761u) >> (32 - HashBits));
                int candidate = head[hash];
                head[hash] = i;
                int distance = i - candidate, matched = 0;
                if (distance <= Window
                    && data[candidate] == (byte)current && data[candidate + 1] == (byte)(current >> 8)
                    && data[candidate + 2] == (byte)(current >> 16) && data[candidate + 3] == (byte)(current >> 24))
                {
                    int max = length - i;
                    if (max > MaxMatch) max = MaxMatch;
                    matched = MinMatch;
                    while (matched < max && data[candidate + matched] == data[i + matched]) matched++;
                }
                if (matched != 0)
                {
                    symbols[n++] = matched << 16 | distance;
                    literalCounts[lengthSymbolOf[matched]]++;
                    distanceCounts[distanceCodeOf[distance]]++;
                    // Every position inside the match enters the table too: the candidates stay recent, which on
                    // images buys 15–25 % smaller files for a third more time than skipping them.
                    for (int k = i + 1, stop = Math.Min(i + matched, last + 1); k < stop; k++)
                        head[(int)(((data[k] | (uint)data[k + 1] << 8 | (uint)data[k + 2] << 16 | (uint)data[k + 3] << 24) * 2654435761u) >> (32 - HashBits))] = k;
                    i += matched;
                    if (i <= last) current = data[i] | (uint)data[i + 1] << 8 | (uint)data[i + 2] << 16 | (uint)data[i + 3] << 24;
                }
                else
                {
                    int literal = (byte)current;
                    symbols[n++] = literal;
                    literalCounts[literal]++;
                    i++;
                    if (i <= last) current = (current >> 8) | (uint)data[i + 3] << 24;
                }
                if (n == BlockSymbols)
                {
                    WriteBlock(data, blockStart, i, n, false);
                    blockStart = i;
                    n = 0;
                }
            }
            for (; i < length; i++)
            {
                symbols[n++] = data[i];
                literalCounts[data[i]]++;
                if (n == BlockSymbols)
                {
                    WriteBlock(data, blockStart, i + 1, n, false);
                    blockStart = i + 1;
                    n = 0;
                }
            }
            WriteBlock(data, blockStart, length, n, true); // possibly empty: just the end-of-block code
            while (_count > 0)
            {
                _output[_o++] = (byte)_bits;
                _bits >>= 8;
                _count -= 8;
            }
            _count = 0;
            return _o;
        }

        internal byte[] Output => _output;

        /// <summary>One block for symbols[0…n), which stand for data[start…end); clears the counts afterwards.</summary>
        void WriteBlock(byte[] data, int start, int end, int n, bool final)
        {
            int[] literalCounts = _literalCounts, distanceCounts = _distanceCounts;
            literalCounts[EndOfBlock] = 1;
            // A block without matches still sends a distance code; two 1-bit codes keep it complete.
            int usedDistances = 0;
            for (int d = 0; d < DistanceSymbols; d++) if (distanceCounts[d] != 0) usedDistances++;
            if (usedDistances < 2)
            {
                if (distanceCounts[0] == 0) distanceCounts[0] = 1;
                else distanceCounts[1] = 1;
            }
            HuffmanCode.BuildLengths(literalCounts, LiteralLengthSymbols, 15, _literalLengths);
            HuffmanCode.BuildCodes(_literalLengths, LiteralLengthSymbols, _literalCodes);
            HuffmanCode.BuildLengths(distanceCounts, DistanceSymbols, 15, _distanceLengths);
            HuffmanCode.BuildCodes(_distanceLengths, DistanceSymbols, _distanceCodes);
            _header.Build(_literalLengths, LiteralLengthSymbols, _distanceLengths, DistanceSymbols);

            long payload = 3 + _header.Bits;
            byte[] extraBits = HuffmanDeflate.SymbolExtraBits;
            for (int s = 0; s < LiteralLengthSymbols; s++) payload += (long)literalCounts[s] * (_literalLengths[s] + extraBits[s]);
            for (int d = 0; d < DistanceSymbols; d++) payload += (long)distanceCounts[d] * (_distanceLengths[d] + DistanceExtraBits[d]);
            int raw = end - start;
            int storedBlocks = Math.Max(1, (raw + MaxStoredBlock - 1) / MaxStoredBlock);
            long storedBits = 8L * (raw + 5L * storedBlocks) + 7;
            EnsureOutput(raw + 5 * storedBlocks + 16);
            if (storedBits <= payload) WriteStored(data, start, raw, final);
            else WriteSymbols(n, final);
            Array.Clear(literalCounts, 0, literalCounts.Length);
            Array.Clear(distanceCounts, 0, distanceCounts.Length);
        }

        void WriteSymbols(int n, bool final)
        {
            byte[] output = _output;
            int o = _o;
            ulong bits = _bits;
            int count = _count;
            HuffmanDeflate.Put((final ? 1 : 0) | (2 << 1), 3, ref bits, ref count, output, ref o); // BTYPE = 10
            _header.Write(ref bits, ref count, output, ref o);

            int[] literal = _literalCodes;
            byte[] literalLengths = _literalLengths;
            int[] lengthEntry = _lengthEntry, distanceEntry = _distanceEntry;
            for (int length = 3; length <= MaxMatch; length++)
            {
                int symbol = HuffmanDeflate.LengthSymbolOf[length], codeBits = literalLengths[symbol];
                int extra = HuffmanDeflate.LengthExtraBits[length];
                lengthEntry[length] = (literal[symbol] | HuffmanDeflate.LengthExtraValue[length] << codeBits) | (codeBits + extra) << 24;
            }
            for (int d = 0; d < DistanceSymbols; d++) distanceEntry[d] = _distanceCodes[d] | _distanceLengths[d] << 16;
            int[] literalEntry = _literalEntry;
            for (int b = 0; b < 256; b++) literalEntry[b] = literal[b] | literalLengths[b] << 16;

            int[] symbols = _symbols;
            byte[] distanceCodeOf = DistanceCodeOf;
            byte[] distanceExtraBits = DistanceExtraBits;
            int[] distanceBase = DistanceBase;
            for (int k = 0; k < n; k++)
            {
                int s = symbols[k];
                if (s < 256)
                {
                    int e = literalEntry[s];
                    bits |= (ulong)(e & 0xFFFF) << count;
                    count += e >> 16;
                }
                else
                {
                    int e = lengthEntry[s >> 16];
                    bits |= (ulong)(e & 0xFFFFFF) << count;
                    count += e >> 24;
                    // A length (≤ 20 bits) and a distance (≤ 28 bits) together could overflow the 64-bit buffer.
                    if (count >= 32)
                    {
                        output[o] = (byte)bits;
                        output[o + 1] = (byte)(bits >> 8);
                        output[o + 2] = (byte)(bits >> 16);
                        output[o + 3] = (byte)(bits >> 24);
                        o += 4;
                        bits >>= 32;
                        count -= 32;
                    }
                    int distance = s & 0xFFFF, code = distanceCodeOf[distance];
                    int d = distanceEntry[code], dBits = d >> 16;
                    bits |= (ulong)((uint)(d & 0xFFFF) | (uint)(distance - distanceBase[code]) << dBits) << count;
                    count += dBits + distanceExtraBits[code];
                }
                if (count >= 32)
                {
                    output[o] = (byte)bits;
                    output[o + 1] = (byte)(bits >> 8);
                    output[o + 2] = (byte)(bits >> 16);
                    output[o + 3] = (byte)(bits >> 24);
                    o += 4;
                    bits >>= 32;
                    count -= 32;
                }
            }
            HuffmanDeflate.Put(_literalCodes[EndOfBlock], _literalLengths[EndOfBlock], ref bits, ref count, output, ref o);
            _o = o;
            _bits = bits;
            _count = count;
        }

        void WriteStored(byte[] data, int start, int raw, bool final)
        {
            int done = 0;
            do
            {
                int n = Math.Min(MaxStoredBlock, raw - done);
                bool last = final && done + n == raw;
                HuffmanDeflate.Put(last ? 1 : 0, 3, ref _bits, ref _count, _output, ref _o); // BTYPE = 00
                while (_count > 0) // to the byte boundary
                {
                    _output[_o++] = (byte)_bits;
                    _bits >>= 8;
                    _count -= 8;
                }
                _bits = 0;
                _count = 0;
                _output[_o++] = (byte)n;
                _output[_o++] = (byte)(n >> 8);
                _output[_o++] = (byte)~n;
                _output[_o++] = (byte)(~n >> 8);
                Buffer.BlockCopy(data, start + done, _output, _o, n);
                _o += n;
                done += n;
            } while (done < raw);
        }

        void EnsureOutput(int more)
        {
            if (_output.Length - _o >= more + 16) return;
            var grown = new byte[Math.Max(_output.Length * 2, _o + more + 1024)];
            Buffer.BlockCopy(_output, 0, grown, 0, _o);
            _output = grown;
        }
    }
}
