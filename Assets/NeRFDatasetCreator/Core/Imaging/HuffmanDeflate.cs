using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Raw DEFLATE (RFC 1951) for PNG's filtered rows, built to be fast on Mono as much as on .NET: no LZ77 search.
    /// Every byte is a literal, except where at least <see cref="MinRepeats"/> bytes in a row each equal the byte a
    /// pixel earlier: such a run is sent as length/distance matches with the distance fixed at the pixel size — the
    /// transparent background of a render (zeros), the flat or linearly varying parts of depth and normal images
    /// after filtering. One dynamic-Huffman block whose codes come from this image's own counts
    /// (<see cref="Compress"/>, from a sample of a large image); stored blocks instead when those would be smaller
    /// (noise).
    /// <para>
    /// The filtered image is held as the zlib payload itself — each row's type byte, then its bytes — packed into
    /// 64-bit words (<see cref="Stream"/>), so both passes walk one flat array with no per-row case. Per word, one bit
    /// per byte says "equals the byte a pixel earlier"; with the next word's bits already computed, a few shifts
    /// mark the bytes that belong to runs of at least <see cref="MinRepeats"/> (any such byte has four equal bytes in
    /// a row within three bytes of it). A word with no such byte — nearly every word of a textured object — is eight
    /// literals: counted (in the sample) into four interleaved histograms, so that no increment waits for the
    /// previous one to the same counter, and written as four two-literal codes joined two by two into a 64-bit
    /// accumulator, with no other branch. The loops keep everything in locals and call nothing per byte, because
    /// Mono inlines little. Not thread-safe: one instance per thread.
    /// </para>
    /// </summary>
    internal sealed class HuffmanDeflate
    {
        /// <summary>
        /// Repeats from which a run is sent as matches rather than literals (a match is at least 3 bytes); the
        /// look-ahead's shifts by 1, 2 and 3 bytes are written for this value.
        /// </summary>
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

        // Per word: one bit per byte (bit 0 of each byte), gathered into one byte by a multiplication: byte k of the
        // word becomes bit k (the partial products never overlap, so nothing carries).
        const ulong OneBitPerByte = 0x0101010101010101UL;
        const ulong GatherBits = 0x0102040810204080UL;
        const ulong Low7 = 0x7F7F7F7F7F7F7F7FUL;
        const ulong High = 0x8080808080808080UL;

        // Trailing zero bits of 1…511 (a run or a stretch of literals in a word's nine-bit view).
        static readonly byte[] TrailingZeros = new byte[512];

        // The order in which code-length code lengths are sent (RFC 1951 §3.2.7).
        static readonly byte[] CodeLengthOrder = { 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15 };

        static HuffmanDeflate()
        {
            for (int v = 1; v < 512; v++)
            {
                int zeros = 0;
                while ((v & (1 << zeros)) == 0) zeros++;
                TrailingZeros[v] = (byte)zeros;
            }
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

        /// <summary>
        /// The zlib payload, little-endian in 64-bit words: per row its filter type byte, then its filtered bytes
        /// (<see cref="PutRow"/>). Bytes past <see cref="StreamBytes"/> are ignored.
        /// </summary>
        internal ulong[] Stream = new ulong[0];

        /// <summary>Words a row scratch needs to hold one row's bytes.</summary>
        internal int RowWords { get; private set; }

        int _bytesPerPixel, _rowBytes, _height;
        readonly int[] _counts = new int[LiteralLengthSymbols];
        readonly int[] _histograms = new int[4 * 256];
        readonly byte[] _lengths = new byte[LiteralLengthSymbols];
        readonly int[] _codes = new int[LiteralLengthSymbols];
        // Per literal: code | length << 16. Per match length: code, extra bits and distance code | total bits << 24.
        readonly int[] _literal = new int[256];
        readonly int[] _match = new int[MaxMatch + 1];
        readonly CodeLengthHeader _header = new CodeLengthHeader();
        // Literals (estimated from the sample) from which a table of literal pairs (65 536 entries) pays for its
        // construction: not for a mask, whose bytes are nearly all runs.
        const long PairTableFrom = 1 << 17;
        bool _pairsPay;
        ulong[] _pairs;
        ulong[] _bitWords = new ulong[0];
        // The block header: at most 5 + 5 + 4 + 19·3 bits and 286 + 30 code lengths of at most 7 + 7 bits.
        readonly byte[] _headerScratch = new byte[1024];
        bool _stored;
        ulong _adlerS1, _adlerS2;
        int _size;

        /// <summary>Sizes <see cref="Stream"/> for an image; call before <see cref="PutRow"/>.</summary>
        internal void Begin(int bytesPerPixel, int rowBytes, int height)
        {
            if (bytesPerPixel < 1 || bytesPerPixel > 4) throw new ArgumentOutOfRangeException(nameof(bytesPerPixel));
            _bytesPerPixel = bytesPerPixel;
            _rowBytes = rowBytes;
            _height = height;
            RowWords = (rowBytes + 7) >> 3;
            // One word beyond the last: the passes read a word ahead.
            long words = ((long)StreamBytes + 7) / 8 + 1;
            if (Stream.Length < words) Stream = new ulong[words];
        }

        /// <summary>Uncompressed length of the zlib payload: a type byte and the row bytes per row.</summary>
        internal int StreamBytes => (_rowBytes + 1) * _height;

        /// <summary>
        /// Places row <paramref name="y"/> (rows in order from 0): its filter type, then its filtered bytes from
        /// <paramref name="filtered"/>, and feeds both to the Adler-32 (RFC 1950) while the row is in the cache.
        /// </summary>
        internal void PutRow(int y, int type, ulong[] filtered)
        {
            int at = y * (_rowBytes + 1);
            Buffer.SetByte(Stream, at, (byte)type);
            Buffer.BlockCopy(filtered, 0, Stream, at + 1, _rowBytes);

            ulong s1 = y == 0 ? 1UL : _adlerS1, s2 = y == 0 ? 0UL : _adlerS2;
            s1 += (uint)type;
            s2 += s1;
            int full = _rowBytes >> 3;
            for (int start = 0; start < full; start += 256)
            {
                // Adler-32 of 8 bytes b0…b7: s1 += Σb, s2 += 8·s1 + Σ(8 − k)·bk; the weighted sums are gathered per
                // byte position in 16-bit lanes (256 words at most: 255·256 fits) and added after each stretch.
                ulong laneEven = 0, laneOdd = 0;
                int end = Math.Min(full, start + 256);
                for (int j = start; j < end; j++)
                {
                    ulong w = filtered[j];
                    s2 += s1 << 3;
                    if (w == 0) continue; // a background's zeros: s1 stays
                    ulong even = w & EvenBytes, odd = (w >> 8) & EvenBytes;
                    s1 += ((even + odd) * LaneSum) >> 48;
                    laneEven += even;
                    laneOdd += odd;
                }
                s2 += Weighted(laneEven, laneOdd);
                s1 %= AdlerModulus;
                s2 %= AdlerModulus;
            }
            if ((_rowBytes & 7) != 0)
            {
                ulong last = filtered[full];
                for (int k = 0; k < (_rowBytes & 7); k++)
                {
                    s1 += (last >> (8 * k)) & 0xFF;
                    s2 += s1;
                }
                s1 %= AdlerModulus;
                s2 %= AdlerModulus;
            }
            _adlerS1 = s1;
            _adlerS2 = s2;
        }

        /// <summary>
        /// Builds the codes from the counts of the symbols the stream will become — all of them for a small image, one
        /// stretch of <see cref="SampleWords"/> words in every <see cref="SampleStride"/> otherwise (a render's rows
        /// are alike enough that the code lengths barely differ; every symbol gets a count of at least one, so
        /// anything the sample missed still has a code) — then codes the stream; <paramref name="adler"/> is the
        /// Adler-32 <see cref="PutRow"/> gathered. Returns the size in bytes of the DEFLATE stream
        /// <see cref="Write"/> will copy: the Huffman block, or stored blocks when those would be smaller (noise).
        /// </summary>
        internal int Compress(out uint adler)
        {
            int[] counts = _counts;
            Array.Clear(counts, 0, counts.Length);
            int[] hist = _histograms;
            Array.Clear(hist, 0, hist.Length);
            int total = StreamBytes, words = (total + 7) >> 3;
            bool sampled = words >= SampleFrom;
            if (!sampled) CountRange(0, words, hist, counts);
            else
                for (int from = 0; from < words; from += SampleStride)
                    CountRange(from, Math.Min(from + SampleWords, words), hist, counts);
            long literals = 0;
            for (int b = 0; b < 256; b++)
            {
                counts[b] = hist[b] + hist[256 + b] + hist[512 + b] + hist[768 + b];
                literals += counts[b];
            }
            _pairsPay = literals * (sampled ? SampleStride / SampleWords : 1) >= PairTableFrom;
            if (sampled)
                for (int symbol = 0; symbol < LiteralLengthSymbols; symbol++) counts[symbol]++;
            counts[EndOfBlock] = 1;

            HuffmanCode.BuildLengths(counts, LiteralLengthSymbols, 15, _lengths);
            HuffmanCode.BuildCodes(_lengths, LiteralLengthSymbols, _codes);
            _header.Build(_lengths, LiteralLengthSymbols, _bytesPerPixel);

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

            adler = (uint)((_adlerS2 << 16) | _adlerS1);
            int blocks = Math.Max(1, (total + MaxStoredBlock - 1) / MaxStoredBlock);
            long storedBytes = total + 5L * blocks;
            long huffmanBytes = Encode(storedBytes);
            _stored = storedBytes <= huffmanBytes;
            _size = (int)(_stored ? storedBytes : huffmanBytes);
            return _size;
        }

        // Images from this many words (128 KiB) on count a sample: one stretch of SampleWords in every SampleStride (1 in 8).
        const int SampleFrom = 1 << 14;
        internal const int SampleWords = 64;
        internal const int SampleStride = 512;

        /// <summary>Adds the symbols of words [from, to) to the counts, as if a run could not go on from before them.</summary>
        void CountRange(int from, int to, int[] hist, int[] counts)
        {
            ulong[] stream = Stream;
            int total = StreamBytes, words = (total + 7) >> 3, tail = total - 8 * (words - 1);
            int shift = 8 * _bytesPerPixel, back = 64 - shift;
            int lastValid = (1 << tail) - 1;
            int repeats = 0;

            // Equal bits of the first word (word 0's first pixel has nothing a pixel earlier); a stretch starts a new run.
            ulong w = stream[from];
            int ePrev = 0, eCur = EqualBits(w, from == 0 ? 0 : stream[from - 1], shift, back);
            if (from == 0) eCur &= ~((1 << _bytesPerPixel) - 1);
            if (from == words - 1) eCur &= lastValid;
            for (int i = from; i < to; i++)
            {
                ulong next = stream[i + 1];
                int eNext = 0;
                if (i + 1 < to)
                {
                    // A byte of x is zero where the byte equals the one a pixel earlier: its top bit set in z then.
                    ulong x = next ^ ((next << shift) | (w >> back));
                    ulong z = ~(((x & Low7) + Low7) | x) & High;
                    eNext = (int)(((z >> 7) * GatherBits) >> 56);
                    if (i + 2 == words) eNext &= lastValid;
                }
                int inRun = 0xFF; // eight equal bytes are a run already
                if (eCur != 0xFF)
                {
                    int window = ePrev | (eCur << 8) | (eNext << 16);
                    int starts = window & (window >> 1) & (window >> 2) & (window >> 3);
                    inRun = ((starts | (starts << 1) | (starts << 2) | (starts << 3)) >> 8) & 0xFF;
                }

                if (i + 1 < words || tail == 8)
                {
                    if (inRun == 0)
                    {
                        if (repeats != 0)
                        {
                            CountMatches(counts, repeats);
                            repeats = 0;
                        }
                        hist[(int)w & 0xFF]++;
                        hist[256 + ((int)(w >> 8) & 0xFF)]++;
                        hist[512 + ((int)(w >> 16) & 0xFF)]++;
                        hist[768 + ((int)(w >> 24) & 0xFF)]++;
                        hist[(int)(w >> 32) & 0xFF]++;
                        hist[256 + ((int)(w >> 40) & 0xFF)]++;
                        hist[512 + ((int)(w >> 48) & 0xFF)]++;
                        hist[768 + (int)(w >> 56)]++;
                    }
                    else if (inRun == 0xFF) repeats += 8;
                    else repeats = CountMixed(w, inRun, 8, repeats, hist, counts);
                }
                else
                {
                    // The last, partial word.
                    repeats = CountMixed(w, inRun, tail, repeats, hist, counts);
                }
                w = next;
                ePrev = eCur;
                eCur = eNext;
            }
            if (repeats != 0) CountMatches(counts, repeats);
        }

        /// <summary>One bit per byte of <paramref name="w"/>: set where it equals the byte a pixel earlier (in w or before it).</summary>
        static int EqualBits(ulong w, ulong before, int shift, int back)
        {
            ulong x = w ^ ((w << shift) | (before >> back));
            x |= x >> 4;
            x |= x >> 2;
            x |= x >> 1;
            return ~(int)(((x & OneBitPerByte) * GatherBits) >> 56) & 0xFF;
        }

        /// <summary>
        /// A word whose first <paramref name="bytes"/> bytes mix runs (bits of <paramref name="inRun"/>) and literals,
        /// taken a stretch at a time; returns the repeats still open at its end.
        /// </summary>
        static int CountMixed(ulong w, int inRun, int bytes, int repeats, int[] hist, int[] counts)
        {
            for (int k = 0; k < bytes;)
            {
                int rest = inRun >> k;
                if ((rest & 1) != 0)
                {
                    int run = TrailingZeros[~rest & 0x1FF];
                    repeats += run;
                    k += run;
                    continue;
                }
                if (repeats != 0)
                {
                    CountMatches(counts, repeats);
                    repeats = 0;
                }
                for (int end = k + TrailingZeros[rest | (1 << (bytes - k))]; k < end; k++)
                    hist[((k & 3) << 8) | ((int)(w >> (8 * k)) & 0xFF)]++;
            }
            return repeats;
        }

        /// <summary>Σ (8 − k)·(sum of byte k) over the words gathered in the two lane accumulators.</summary>
        static ulong Weighted(ulong even, ulong odd)
        {
            return 8 * (even & 0xFFFF) + 6 * ((even >> 16) & 0xFFFF) + 4 * ((even >> 32) & 0xFFFF) + 2 * (even >> 48)
                 + 7 * (odd & 0xFFFF) + 5 * ((odd >> 16) & 0xFFFF) + 3 * ((odd >> 32) & 0xFFFF) + (odd >> 48);
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

        /// <summary>Copies the DEFLATE stream <see cref="Compress"/> made (<see cref="Compress"/>'s size) to <paramref name="output"/>[at].</summary>
        internal void Write(byte[] output, int at)
        {
            if (_stored) WriteStored(output, at);
            else Buffer.BlockCopy(_bitWords, 0, output, at, _size);
        }

        /// <summary>
        /// Codes the stream into <see cref="_bitWords"/> with the codes built; returns its size in bytes, or a size
        /// of at least <paramref name="storedBytes"/> as soon as it is clear that stored blocks will be smaller.
        /// </summary>
        long Encode(long storedBytes)
        {
            // The block header goes through the shared byte-wise writer into a small scratch, then into the words.
            ulong headerBits = 1 | (2 << 1); // BFINAL = 1, BTYPE = 10 (dynamic Huffman)
            int headerCount = 3, headerBytes = 0;
            _header.Write(ref headerBits, ref headerCount, _headerScratch, ref headerBytes);

            // The stream is built as 64-bit words (least significant bit first, as DEFLATE packs bits) and copied
            // into the file at the end: one store per 64 bits. Coding stops once it has passed the stored blocks'
            // size; before that check, one word's step adds at most 8 literals of 15 bits and the matches of the run
            // it ends, at most 21 bits per 258 bytes of the payload: a twelfth of its size bounds them.
            int total = StreamBytes;
            int limit = (int)(storedBytes / 8) + 1;
            long capacity = limit + total / 96 + headerBytes / 8 + 8;
            if (_bitWords.Length < capacity) _bitWords = new ulong[capacity];
            ulong[] buf = _bitWords;
            ulong acc = 0;
            int n = 0, o = 0;
            for (int i = 0; i < headerBytes; i++) Put64(_headerScratch[i], 8, ref acc, ref n, buf, ref o);
            Put64(headerBits, headerCount, ref acc, ref n, buf, ref o);

            int[] literal = _literal;
            int[] match = _match;
            ulong[] pairs = _pairsPay ? BuildPairs() : null;
            ulong[] stream = Stream;
            int words = (total + 7) >> 3, tail = total - 8 * (words - 1);
            int shift = 8 * _bytesPerPixel, back = 64 - shift;
            int lastValid = (1 << tail) - 1;
            int repeats = 0;

            // The same walk as CountRange's, written out again: a per-word call would cost Mono more than the coding.
            ulong w = stream[0];
            int ePrev = 0, eCur = EqualBits(w, 0, shift, back) & ~((1 << _bytesPerPixel) - 1);
            if (words == 1) eCur &= lastValid;
            for (int i = 0; i < words; i++)
            {
                ulong next = stream[i + 1];
                int eNext = 0;
                if (i + 1 < words)
                {
                    // A byte of x is zero where the byte equals the one a pixel earlier: its top bit set in z then.
                    ulong x = next ^ ((next << shift) | (w >> back));
                    ulong z = ~(((x & Low7) + Low7) | x) & High;
                    eNext = (int)(((z >> 7) * GatherBits) >> 56);
                    if (i + 2 == words) eNext &= lastValid;
                }
                int inRun = 0xFF; // eight equal bytes are a run already
                if (eCur != 0xFF)
                {
                    int window = ePrev | (eCur << 8) | (eNext << 16);
                    int starts = window & (window >> 1) & (window >> 2) & (window >> 3);
                    inRun = ((starts | (starts << 1) | (starts << 2) | (starts << 3)) >> 8) & 0xFF;
                }
                int bytes = i + 1 < words ? 8 : tail;
                if (inRun == 0 && bytes == 8 && pairs != null)
                {
                    if (repeats != 0)
                    {
                        PutMatches(repeats, ref acc, ref n, buf, ref o);
                        repeats = 0;
                    }
                    // Eight literals as four two-literal codes (each at most 30 bits, its length above them), joined
                    // two by two: at most 60 bits go into the accumulator at once.
                    ulong pair = pairs[(int)w & 0xFFFF], pair2 = pairs[(int)(w >> 16) & 0xFFFF];
                    int length = (int)(pair >> 32);
                    ulong code = (pair & 0xFFFFFFFF) | ((pair2 & 0xFFFFFFFF) << length);
                    length += (int)(pair2 >> 32);
                    acc |= code << n;
                    n += length;
                    if (n >= 64)
                    {
                        buf[o++] = acc;
                        n -= 64;
                        acc = code >> (length - n);
                    }
                    pair = pairs[(int)(w >> 32) & 0xFFFF];
                    pair2 = pairs[(int)(w >> 48)];
                    length = (int)(pair >> 32);
                    code = (pair & 0xFFFFFFFF) | ((pair2 & 0xFFFFFFFF) << length);
                    length += (int)(pair2 >> 32);
                    acc |= code << n;
                    n += length;
                    if (n >= 64)
                    {
                        buf[o++] = acc;
                        n -= 64;
                        acc = code >> (length - n);
                    }
                }
                else if (inRun == 0xFF) repeats += 8;
                else
                {
                    // Stretches of run and of literals, as CountMixed takes them.
                    for (int k = 0; k < bytes;)
                    {
                        int rest = inRun >> k;
                        if ((rest & 1) != 0)
                        {
                            int run = TrailingZeros[~rest & 0x1FF];
                            repeats += run;
                            k += run;
                            continue;
                        }
                        if (repeats != 0)
                        {
                            PutMatches(repeats, ref acc, ref n, buf, ref o);
                            repeats = 0;
                        }
                        for (int end = k + TrailingZeros[rest | (1 << (bytes - k))]; k < end; k++)
                        {
                            int e = literal[(int)(w >> (8 * k)) & 0xFF];
                            ulong code = (ulong)(e & 0xFFFF);
                            int length = e >> 16;
                            acc |= code << n;
                            n += length;
                            if (n >= 64)
                            {
                                buf[o++] = acc;
                                n -= 64;
                                acc = code >> (length - n);
                            }
                        }
                    }
                }
                if (o >= limit) return storedBytes;
                w = next;
                ePrev = eCur;
                eCur = eNext;
            }
            if (repeats != 0) PutMatches(repeats, ref acc, ref n, buf, ref o);
            Put64((ulong)_codes[EndOfBlock], _lengths[EndOfBlock], ref acc, ref n, buf, ref o);
            if (n > 0) buf[o] = acc;
            return 8 * o + (n + 7) / 8;
        }

        /// <summary>A run of repeats as matches at the pixel distance, cut as <see cref="CountMatches"/> cuts it.</summary>
        void PutMatches(int repeats, ref ulong acc, ref int n, ulong[] buf, ref int o)
        {
            while (repeats > 0)
            {
                int m = repeats > MaxMatch ? MaxMatch : repeats;
                if (repeats - m > 0 && repeats - m < 3) m = repeats - 3;
                repeats -= m;
                Put64((ulong)(_match[m] & 0xFFFFFF), _match[m] >> 24, ref acc, ref n, buf, ref o);
            }
        }

        /// <summary>
        /// Appends <paramref name="length"/> ≤ 32 bits to a stream of 64-bit words (the hot loop inlines the same
        /// steps); <paramref name="code"/> has no bits above its length.
        /// </summary>
        static void Put64(ulong code, int length, ref ulong acc, ref int n, ulong[] buf, ref int o)
        {
            acc |= code << n;
            n += length;
            if (n >= 64)
            {
                buf[o++] = acc;
                n -= 64;
                // n < length here, so the shift is 1…length: the bits of the code that did not fit.
                acc = code >> (length - n);
            }
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
            // Stored blocks cut the payload every 65 535 bytes.
            int length = StreamBytes, done = 0;
            do
            {
                int n = Math.Min(MaxStoredBlock, length - done);
                output[o++] = (byte)(done + n == length ? 1 : 0); // BFINAL, BTYPE = 00, then padding to the byte
                output[o++] = (byte)n;
                output[o++] = (byte)(n >> 8);
                output[o++] = (byte)~n;
                output[o++] = (byte)(~n >> 8);
                Buffer.BlockCopy(Stream, done, output, o, n);
                o += n;
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
