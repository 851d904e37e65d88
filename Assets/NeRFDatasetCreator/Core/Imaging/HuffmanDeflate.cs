using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Raw DEFLATE (RFC 1951) for PNG's filtered rows, built to be fast on Mono as much as on .NET: no LZ77 search.
    /// Every byte is a literal, except where a byte equals the one a pixel earlier: a run of such bytes is sent as
    /// length/distance matches with the distance fixed at the pixel size — the transparent background of a render
    /// (zeros), the flat or linearly varying parts of depth and normal images after filtering. One dynamic-Huffman
    /// block whose codes come from this image's own counts (<see cref="Measure"/>), so the exact size is known
    /// before anything is written; stored blocks instead when those would be smaller (noise).
    /// <para>
    /// The rows are held as 64-bit words (<see cref="Words"/>, filled by <see cref="PngWordFilter"/>): a whole word
    /// of repeats is one comparison, and the Adler-32 of a word is a few multiplications. The loops keep everything in
    /// locals and call nothing per byte, because Mono inlines little. Not thread-safe: one instance per thread.
    /// </para>
    /// </summary>
    internal sealed class HuffmanDeflate
    {
        /// <summary>Repeats from which a run is sent as matches rather than literals (a match is at least 3 bytes).</summary>
        internal const int MinRepeats = 4;

        const int LiteralLengthSymbols = 286;
        const int EndOfBlock = 256;
        const int MaxMatch = 258;
        const int MaxStoredBlock = 65535;
        const uint AdlerModulus = 65521;
        const ulong EvenBytes = 0x00FF00FF00FF00FFUL;
        const ulong LaneSum = 0x0001000100010001UL;

        // RFC 1951 §3.2.5: the length symbol, its extra-bit count and its base length for every match length 3…258.
        // Shared with Lz77Deflate.
        internal static readonly short[] LengthSymbolOf = new short[MaxMatch + 1];
        internal static readonly byte[] LengthExtraBits = new byte[MaxMatch + 1];
        internal static readonly short[] LengthExtraValue = new short[MaxMatch + 1];
        internal static readonly byte[] SymbolExtraBits = new byte[LiteralLengthSymbols];

        // Per word: one bit per byte (bit 0 of each byte), gathered into one byte by a multiplication, then the
        // zero bits (repeats) at its bottom and top from these tables; LowBytes[n] masks the lowest n bytes.
        const ulong OneBitPerByte = 0x0101010101010101UL;
        const ulong GatherBits = 0x0102040810204080UL;
        static readonly byte[] TrailingZeroBits = new byte[256];
        static readonly byte[] LeadingZeroBits = new byte[256];
        static readonly ulong[] LowBytes = new ulong[9];

        // The order in which code-length code lengths are sent (RFC 1951 §3.2.7).
        static readonly byte[] CodeLengthOrder = { 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15 };

        static HuffmanDeflate()
        {
            for (int bitsSet = 1; bitsSet < 256; bitsSet++)
            {
                int low = 0, high = 0;
                while ((bitsSet & (1 << low)) == 0) low++;
                while ((bitsSet & (0x80 >> high)) == 0) high++;
                TrailingZeroBits[bitsSet] = (byte)low;
                LeadingZeroBits[bitsSet] = (byte)high;
            }
            for (int n = 0; n < 8; n++) LowBytes[n] = (1UL << (8 * n)) - 1;
            LowBytes[8] = ulong.MaxValue;

            int[] baseLength = { 3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258 };
            int[] extra = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
            for (int i = 0; i < baseLength.Length; i++)
            {
                SymbolExtraBits[257 + i] = (byte)extra[i];
                // 227…257 is symbol 284 (5 extra bits would reach 258, but 258 has its own symbol, 285).
                int end = i + 1 < baseLength.Length ? baseLength[i + 1] : MaxMatch + 1;
                for (int length = baseLength[i]; length < end; length++)
                {
                    LengthSymbolOf[length] = (short)(257 + i);
                    LengthExtraBits[length] = (byte)extra[i];
                    LengthExtraValue[length] = (short)(length - baseLength[i]);
                }
            }
        }

        /// <summary>Filtered rows, <see cref="RowWords"/> words each; bytes past a row's end are ignored.</summary>
        internal ulong[] Words = new ulong[0];

        /// <summary>The filter type of each row, sent before it.</summary>
        internal byte[] Types = new byte[0];

        internal int RowWords { get; private set; }

        int _bytesPerPixel, _rowBytes, _height;
        readonly int[] _counts = new int[LiteralLengthSymbols];
        readonly byte[] _lengths = new byte[LiteralLengthSymbols];
        readonly int[] _codes = new int[LiteralLengthSymbols];
        // Per literal: code | length << 16. Per match length: code, extra bits and distance code | total bits << 24.
        readonly int[] _literal = new int[256];
        readonly int[] _match = new int[MaxMatch + 1];
        readonly CodeLengthHeader _header = new CodeLengthHeader();
        // Literals from which a table of literal pairs (65 536 entries) pays for its construction.
        const long PairTableFrom = 1 << 17;
        ulong[] _pairs;
        long _literalCount;
        bool _stored;
        long _payloadBits;
        int _size;

        /// <summary>Sizes <see cref="Words"/> and <see cref="Types"/> for an image; call before filling them.</summary>
        internal void Begin(int bytesPerPixel, int rowBytes, int height)
        {
            if (bytesPerPixel < 1 || bytesPerPixel > 4) throw new ArgumentOutOfRangeException(nameof(bytesPerPixel));
            _bytesPerPixel = bytesPerPixel;
            _rowBytes = rowBytes;
            _height = height;
            RowWords = (rowBytes + 7) >> 3;
            long words = (long)RowWords * height;
            if (Words.Length < words) Words = new ulong[words];
            if (Types.Length < height) Types = new byte[height];
        }

        /// <summary>Uncompressed length of the zlib payload: a type byte and the row bytes per row.</summary>
        internal int StreamBytes => (_rowBytes + 1) * _height;

        /// <summary>
        /// Counts the symbols the rows will become and their Adler-32 (RFC 1950), builds the codes and returns the
        /// exact size in bytes of the DEFLATE stream <see cref="Write"/> will produce.
        /// </summary>
        internal int Measure(out uint adler)
        {
            int[] counts = _counts;
            Array.Clear(counts, 0, counts.Length);
            ulong[] words = Words;
            byte[] types = Types;
            int rowWords = RowWords, lastWord = rowWords - 1, lastBytes = _rowBytes - 8 * lastWord;
            int shift = 8 * _bytesPerPixel, back = 64 - shift, typeShift = 64 - shift;
            ulong firstRowForbid = FirstRowForbid(_bytesPerPixel);
            ulong previous = 0; // the 8 stream bytes before the current position, the latest in the top byte
            ulong s1 = 1, s2 = 0, laneEven = 0, laneOdd = 0;
            int lanes = 0;
            int repeats = 0;
            ulong pending = 0; // the bytes of a run still too short for a match, the first in the lowest byte
            for (int y = 0; y < _height; y++)
            {
                int t = types[y];
                if (y > 0 && t == (int)((previous >> typeShift) & 0xFF))
                {
                    if (repeats < MinRepeats) pending |= (ulong)t << (8 * repeats);
                    repeats++;
                }
                else
                {
                    if (repeats != 0)
                    {
                        if (repeats < MinRepeats)
                            for (int r = 0; r < repeats; r++) counts[(int)(pending >> (8 * r)) & 0xFF]++;
                        else CountMatches(counts, repeats);
                        repeats = 0;
                        pending = 0;
                    }
                    counts[t]++;
                }
                s1 += (uint)t;
                s2 += s1;
                previous = (previous >> 8) | ((ulong)t << 56);

                int rowStart = y * rowWords;
                for (int j = 0; j < rowWords; j++)
                {
                    ulong w = words[rowStart + j];
                    ulong equal = w ^ ((w << shift) | (previous >> back));
                    if (j == 0 && y == 0) equal |= firstRowForbid;
                    int n = j == lastWord ? lastBytes : 8;
                    if (n == 8)
                    {
                        // Adler-32 of 8 bytes b0…b7: s1 += Σb, s2 += 8·s1 + Σ(8 − k)·bk; the weighted sums are
                        // gathered per byte position in 16-bit lanes and added at the end of the row.
                        ulong even = w & EvenBytes, odd = (w >> 8) & EvenBytes;
                        s2 += s1 << 3;
                        s1 += ((even + odd) * LaneSum) >> 48;
                        laneEven += even;
                        laneOdd += odd;
                        if (++lanes == 256)
                        {
                            s2 += Weighted(laneEven, laneOdd);
                            laneEven = laneOdd = 0;
                            lanes = 0;
                        }
                        previous = w;
                        if (equal == 0)
                        {
                            repeats += 8;
                            continue;
                        }
                    }
                    else
                    {
                        for (int k = 0; k < 8 * n; k += 8)
                        {
                            s1 += (w >> k) & 0xFF;
                            s2 += s1;
                        }
                        previous = (previous >> (8 * n)) | (w << (64 - 8 * n));
                        equal |= ~0UL << (8 * n); // bytes past the row's end are never sent
                    }
                    // Which bytes differ from the byte a pixel earlier, one bit each: the repeats at the bottom of the
                    // word end the current run, those at the top start the next one, everything between is sent as
                    // literals (a short run inside one word is not worth a branch per byte).
                    ulong differs = equal | (equal >> 4);
                    differs |= differs >> 2;
                    differs |= differs >> 1;
                    int nonzero = (int)(((differs & OneBitPerByte) * GatherBits) >> 56);
                    int low = TrailingZeroBits[nonzero], top = n == 8 ? LeadingZeroBits[nonzero] : 0, end = n - top;
                    if (repeats < MinRepeats) pending |= (w & LowBytes[low]) << (8 * repeats);
                    repeats += low;
                    if (repeats != 0)
                    {
                        if (repeats < MinRepeats)
                            for (int r = 0; r < repeats; r++) counts[(int)(pending >> (8 * r)) & 0xFF]++;
                        else CountMatches(counts, repeats);
                    }
                    for (int k = 8 * low; k < 8 * end; k += 8) counts[(int)(w >> k) & 0xFF]++;
                    repeats = top;
                    pending = top == 0 ? 0 : w >> (8 * end);
                }
                s2 += Weighted(laneEven, laneOdd);
                laneEven = laneOdd = 0;
                lanes = 0;
                s1 %= AdlerModulus;
                s2 %= AdlerModulus;
            }
            if (repeats != 0)
            {
                if (repeats < MinRepeats)
                    for (int r = 0; r < repeats; r++) counts[(int)(pending >> (8 * r)) & 0xFF]++;
                else CountMatches(counts, repeats);
            }
            adler = (uint)((s2 << 16) | s1);
            counts[EndOfBlock] = 1;

            HuffmanCode.BuildLengths(counts, LiteralLengthSymbols, 15, _lengths);
            HuffmanCode.BuildCodes(_lengths, LiteralLengthSymbols, _codes);
            long matches = 0;
            long bits = 0;
            _literalCount = 0;
            for (int b = 0; b < 256; b++) _literalCount += counts[b];
            for (int s = 0; s < LiteralLengthSymbols; s++)
            {
                bits += (long)counts[s] * (_lengths[s] + SymbolExtraBits[s]);
                if (s > EndOfBlock) matches += counts[s];
            }
            bits += matches; // each match's distance code is one bit
            _header.Build(_lengths, LiteralLengthSymbols, _bytesPerPixel);
            _payloadBits = 3 + _header.Bits + bits;

            long huffmanBytes = (_payloadBits + 7) / 8;
            int length = StreamBytes;
            int blocks = Math.Max(1, (length + MaxStoredBlock - 1) / MaxStoredBlock);
            long storedBytes = length + 5L * blocks;
            _stored = storedBytes <= huffmanBytes;
            _size = (int)(_stored ? storedBytes : huffmanBytes);

            for (int b = 0; b < 256; b++) _literal[b] = _codes[b] | (_lengths[b] << 16);
            // The distance code: two 1-bit codes, for distances 1 and the pixel size (or 1 and 2 for one byte per
            // pixel); the canonical order gives the pixel size's code the bit 1 unless it is distance 1.
            int distanceBit = _bytesPerPixel > 1 ? 1 : 0;
            for (int m = 3; m <= MaxMatch; m++)
            {
                int symbol = LengthSymbolOf[m];
                int codeBits = _lengths[symbol], extraBits = LengthExtraBits[m];
                int pattern = _codes[symbol] | (LengthExtraValue[m] << codeBits) | (distanceBit << (codeBits + extraBits));
                _match[m] = pattern | ((codeBits + extraBits + 1) << 24);
            }
            return _size;
        }

        /// <summary>Σ (8 − k)·(sum of byte k) over the words gathered in the two lane accumulators.</summary>
        static ulong Weighted(ulong even, ulong odd)
        {
            return 8 * (even & 0xFFFF) + 6 * ((even >> 16) & 0xFFFF) + 4 * ((even >> 32) & 0xFFFF) + 2 * (even >> 48)
                 + 7 * (odd & 0xFFFF) + 5 * ((odd >> 16) & 0xFFFF) + 3 * ((odd >> 32) & 0xFFFF) + (odd >> 48);
        }

        /// <summary>
        /// Marks the first row's bytes that have no byte a pixel earlier in the stream (the type byte is the first),
        /// so that they are never taken for repeats.
        /// </summary>
        static ulong FirstRowForbid(int bytesPerPixel)
        {
            ulong forbid = 0;
            for (int k = 0; k < bytesPerPixel - 1; k++) forbid |= 1UL << (8 * k);
            return forbid;
        }

        /// <summary>How a run of repeats is cut into matches; <see cref="Write"/> cuts it the same way.</summary>
        static void CountMatches(int[] counts, int repeats)
        {
            while (repeats > 0)
            {
                int m = repeats > MaxMatch ? MaxMatch : repeats;
                if (repeats - m > 0 && repeats - m < 3) m = repeats - 3;
                counts[LengthSymbolOf[m]]++;
                repeats -= m;
            }
        }

        /// <summary>Writes the stream <see cref="Measure"/> sized at <paramref name="output"/>[at].</summary>
        internal void Write(byte[] output, int at)
        {
            if (_stored)
            {
                WriteStored(output, at);
                return;
            }

            ulong bits = 1 | (2 << 1); // BFINAL = 1, BTYPE = 10 (dynamic Huffman)
            int count = 3;
            int o = at;
            _header.Write(ref bits, ref count, output, ref o);

            int[] literal = _literal;
            int[] match = _match;
            ulong[] pairs = _literalCount >= PairTableFrom ? BuildPairs() : null;
            ulong[] words = Words;
            byte[] types = Types;
            int rowWords = RowWords, lastWord = rowWords - 1, lastBytes = _rowBytes - 8 * lastWord;
            int shift = 8 * _bytesPerPixel, back = 64 - shift, typeShift = 64 - shift;
            ulong firstRowForbid = FirstRowForbid(_bytesPerPixel);
            ulong previous = 0;
            int repeats = 0;
            ulong pending = 0;
            for (int y = 0; y < _height; y++)
            {
                int t = types[y];
                if (y > 0 && t == (int)((previous >> typeShift) & 0xFF))
                {
                    if (repeats < MinRepeats) pending |= (ulong)t << (8 * repeats);
                    repeats++;
                }
                else
                {
                    if (repeats != 0)
                    {
                        FlushRepeats(repeats, pending, ref bits, ref count, output, ref o);
                        repeats = 0;
                        pending = 0;
                    }
                    Put(literal[t] & 0xFFFF, literal[t] >> 16, ref bits, ref count, output, ref o);
                }
                previous = (previous >> 8) | ((ulong)t << 56);

                int rowStart = y * rowWords;
                for (int j = 0; j < rowWords; j++)
                {
                    ulong w = words[rowStart + j];
                    ulong equal = w ^ ((w << shift) | (previous >> back));
                    if (j == 0 && y == 0) equal |= firstRowForbid;
                    int n = j == lastWord ? lastBytes : 8;
                    if (n == 8)
                    {
                        previous = w;
                        if (equal == 0)
                        {
                            repeats += 8;
                            continue;
                        }
                    }
                    else
                    {
                        previous = (previous >> (8 * n)) | (w << (64 - 8 * n));
                        equal |= ~0UL << (8 * n);
                    }
                    // The same cut as in Measure.
                    ulong differs = equal | (equal >> 4);
                    differs |= differs >> 2;
                    differs |= differs >> 1;
                    int nonzero = (int)(((differs & OneBitPerByte) * GatherBits) >> 56);
                    int low = TrailingZeroBits[nonzero], top = n == 8 ? LeadingZeroBits[nonzero] : 0, end = n - top;
                    if (repeats < MinRepeats) pending |= (w & LowBytes[low]) << (8 * repeats);
                    repeats += low;
                    if (repeats != 0)
                    {
                        if (repeats < MinRepeats)
                        {
                            for (int r = 0; r < repeats; r++)
                            {
                                int e = literal[(int)(pending >> (8 * r)) & 0xFF];
                                bits |= (ulong)(e & 0xFFFF) << count;
                                count += e >> 16;
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
                        }
                        else
                        {
                            while (repeats > 0)
                            {
                                int m = repeats > MaxMatch ? MaxMatch : repeats;
                                if (repeats - m > 0 && repeats - m < 3) m = repeats - 3;
                                repeats -= m;
                                int e = match[m];
                                bits |= (ulong)(e & 0xFFFFFF) << count;
                                count += e >> 24;
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
                        }
                    }
                    int k = 8 * low, stop = 8 * end;
                    if (pairs != null)
                    {
                        // Two literals per lookup: their codes joined (at most 30 bits) with the total length above.
                        for (; k + 16 <= stop; k += 16)
                        {
                            ulong pair = pairs[(int)(w >> k) & 0xFFFF];
                            bits |= (pair & 0xFFFFFFFF) << count;
                            count += (int)(pair >> 32);
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
                    }
                    for (; k < stop; k += 8)
                    {
                        int entry = literal[(int)(w >> k) & 0xFF];
                        bits |= (ulong)(entry & 0xFFFF) << count;
                        count += entry >> 16;
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
                    repeats = top;
                    pending = top == 0 ? 0 : w >> (8 * end);
                }
            }
            if (repeats != 0) FlushRepeats(repeats, pending, ref bits, ref count, output, ref o);
            Put(_codes[EndOfBlock], _lengths[EndOfBlock], ref bits, ref count, output, ref o);
            while (count > 0)
            {
                output[o++] = (byte)bits;
                bits >>= 8;
                count -= 8;
            }
            if (o - at != _size) throw new InvalidOperationException($"DEFLATE stream is {o - at} bytes; {_size} were measured.");
        }

        /// <summary>The codes of every two literals (the first in the low byte of the index), for <see cref="Write"/>.</summary>
        ulong[] BuildPairs()
        {
            ulong[] pairs = _pairs ?? (_pairs = new ulong[65536]);
            int[] literal = _literal;
            for (int first = 0; first < 256; first++)
            {
                int a = literal[first], aBits = a >> 16;
                if (aBits == 0) continue; // never sent: its pairs are never looked up
                ulong aCode = (ulong)(a & 0xFFFF);
                for (int second = 0; second < 256; second++)
                {
                    int b = literal[second];
                    pairs[(second << 8) | first] = (aCode | ((ulong)(b & 0xFFFF) << aBits)) | ((ulong)(aBits + (b >> 16)) << 32);
                }
            }
            return pairs;
        }

        void FlushRepeats(int repeats, ulong pending, ref ulong bits, ref int count, byte[] output, ref int o)
        {
            if (repeats < MinRepeats)
            {
                for (int r = 0; r < repeats; r++)
                {
                    int e = _literal[(int)(pending >> (8 * r)) & 0xFF];
                    Put(e & 0xFFFF, e >> 16, ref bits, ref count, output, ref o);
                }
                return;
            }
            while (repeats > 0)
            {
                int m = repeats > MaxMatch ? MaxMatch : repeats;
                if (repeats - m > 0 && repeats - m < 3) m = repeats - 3;
                repeats -= m;
                Put(_match[m] & 0xFFFFFF, _match[m] >> 24, ref bits, ref count, output, ref o);
            }
        }

        /// <summary>Appends <paramref name="n"/> ≤ 32 bits; for the few symbols outside the hot loop.</summary>
        internal static void Put(int value, int n, ref ulong bits, ref int count, byte[] output, ref int o)
        {
            bits |= (ulong)(uint)value << count;
            count += n;
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

        void WriteStored(byte[] output, int o)
        {
            // The stream is a type byte and the row bytes per row; stored blocks cut it every 65 535 bytes.
            int length = StreamBytes, done = 0, y = 0, inRow = -1; // inRow −1: the row's type byte is next
            do
            {
                int n = Math.Min(MaxStoredBlock, length - done);
                output[o++] = (byte)(done + n == length ? 1 : 0); // BFINAL, BTYPE = 00, then padding to the byte
                output[o++] = (byte)n;
                output[o++] = (byte)(n >> 8);
                output[o++] = (byte)~n;
                output[o++] = (byte)(~n >> 8);
                int left = n;
                while (left > 0)
                {
                    if (inRow < 0)
                    {
                        output[o++] = Types[y];
                        inRow = 0;
                        left--;
                        continue;
                    }
                    int take = Math.Min(left, _rowBytes - inRow);
                    Buffer.BlockCopy(Words, y * RowWords * 8 + inRow, output, o, take);
                    o += take;
                    left -= take;
                    inRow += take;
                    if (inRow == _rowBytes)
                    {
                        y++;
                        inRow = -1;
                    }
                }
                done += n;
            } while (done < length);
        }

        /// <summary>
        /// The dynamic block's header after BFINAL/BTYPE: HLIT, HDIST, HCLEN, the code-length code and the literal/length
        /// and distance code lengths run-length coded with it (RFC 1951 §3.2.7). The distance code has two 1-bit codes
        /// (a complete code, which every inflater accepts), of which only the pixel size's is used.
        /// </summary>
        internal sealed class CodeLengthHeader
        {
            readonly int[] _tokens = new int[LiteralLengthSymbols + 32]; // symbol | extra value << 8
            readonly int[] _counts = new int[19];
            readonly byte[] _lengths = new byte[19];
            readonly int[] _codes = new int[19];
            int _tokenCount, _literalCodes, _distanceCodes, _codeLengthCodes;

            internal long Bits { get; private set; }

            internal void Build(byte[] literalLengths, int symbols, int bytesPerPixel)
            {
                // Two 1-bit distance codes: distance 1 and the pixel size (distances 1–4 are codes 0–3).
                int distanceCodes = bytesPerPixel > 1 ? bytesPerPixel : 2;
                var distanceLengths = new byte[distanceCodes];
                distanceLengths[0] = 1;
                distanceLengths[distanceCodes - 1] = 1;
                Build(literalLengths, symbols, distanceLengths, distanceCodes);
            }

            /// <summary>The header for any literal/length and distance code lengths (unused trailing codes are cut).</summary>
            internal void Build(byte[] literalLengths, int symbols, byte[] distanceLengths, int distanceSymbols)
            {
                _distanceCodes = distanceSymbols;
                while (_distanceCodes > 1 && distanceLengths[_distanceCodes - 1] == 0) _distanceCodes--;
                _literalCodes = symbols;
                while (_literalCodes > 257 && literalLengths[_literalCodes - 1] == 0) _literalCodes--;
                Array.Clear(_counts, 0, _counts.Length);
                _tokenCount = 0;
                Tokenise(literalLengths, _literalCodes);
                Tokenise(distanceLengths, _distanceCodes);
                HuffmanCode.BuildLengths(_counts, 19, 7, _lengths);
                HuffmanCode.BuildCodes(_lengths, 19, _codes);
                _codeLengthCodes = 19;
                while (_codeLengthCodes > 4 && _lengths[CodeLengthOrder[_codeLengthCodes - 1]] == 0) _codeLengthCodes--;
                long bits = 5 + 5 + 4 + 3L * _codeLengthCodes;
                for (int t = 0; t < _tokenCount; t++)
                {
                    int symbol = _tokens[t] & 0xFF;
                    bits += _lengths[symbol] + ExtraBits(symbol);
                }
                Bits = bits;
            }

            void Tokenise(byte[] lengths, int n)
            {
                for (int i = 0; i < n;)
                {
                    int value = lengths[i], run = 1;
                    while (i + run < n && lengths[i + run] == value) run++;
                    i += run;
                    if (value == 0)
                    {
                        while (run >= 11) { int r = Math.Min(run, 138); Add(18, r - 11); run -= r; }
                        if (run >= 3) { Add(17, run - 3); run = 0; }
                        while (run-- > 0) Add(0, 0);
                    }
                    else
                    {
                        Add(value, 0);
                        run--;
                        while (run >= 3) { int r = Math.Min(run, 6); Add(16, r - 3); run -= r; }
                        while (run-- > 0) Add(value, 0);
                    }
                }
            }

            void Add(int symbol, int extra)
            {
                _tokens[_tokenCount++] = symbol | (extra << 8);
                _counts[symbol]++;
            }

            static int ExtraBits(int symbol) => symbol == 16 ? 2 : symbol == 17 ? 3 : symbol == 18 ? 7 : 0;

            internal void Write(ref ulong bits, ref int count, byte[] output, ref int o)
            {
                Put(_literalCodes - 257, 5, ref bits, ref count, output, ref o);
                Put(_distanceCodes - 1, 5, ref bits, ref count, output, ref o);
                Put(_codeLengthCodes - 4, 4, ref bits, ref count, output, ref o);
                for (int i = 0; i < _codeLengthCodes; i++) Put(_lengths[CodeLengthOrder[i]], 3, ref bits, ref count, output, ref o);
                for (int t = 0; t < _tokenCount; t++)
                {
                    int symbol = _tokens[t] & 0xFF;
                    Put(_codes[symbol], _lengths[symbol], ref bits, ref count, output, ref o);
                    int extra = ExtraBits(symbol);
                    if (extra > 0) Put(_tokens[t] >> 8, extra, ref bits, ref count, output, ref o);
                }
            }
        }
    }
}
