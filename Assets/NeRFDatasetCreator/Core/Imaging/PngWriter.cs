using System;
using System.IO;
using System.IO.Compression;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Encodes PNG files (PNG specification, 3rd ed.): 8-bit gray, RGB, RGBA and 16-bit gray, non-interlaced, one
    /// IDAT chunk holding a zlib stream (RFC 1950). The DEFLATE data comes from this project's
    /// <see cref="HuffmanDeflate"/> (the default, <see cref="PngCompression.Huffman"/>), from its greedy LZ77
    /// counterpart <see cref="Lz77Deflate"/> (<see cref="PngCompression.Lz77"/>: smaller files, half the speed) or from
    /// System.IO.Compression.DeflateStream (the other levels, kept as the reference the tests compare against).
    /// <para>
    /// Thread-safe: every call uses its own thread's scratch buffers ([ThreadStatic]) and shares only immutable
    /// tables, so many frames can be encoded at once. Once a thread's scratch has grown to the working size, a
    /// Huffman call allocates the returned array and a few small tables; a DeflateStream call also its stream.
    /// </para>
    /// </summary>
    public static class PngWriter
    {
        /// <summary>
        /// The compression used when none is given: Huffman, several times faster than DeflateStream's level 6 on both
        /// runtimes (Mono's DeflateStream always runs level 6), at the price of larger files on grainy renders and
        /// smooth depth images, where level 6's LZ77 search finds repeats that Huffman coding alone cannot use. The
        /// figures and the size analysis are in Documentation~/pixels.md §6; pass <see cref="PngCompression.Optimal"/>
        /// for the smallest files.
        /// </summary>
        public const PngCompression DefaultCompression = PngCompression.Huffman;

        /// <summary>
        /// The row filter used when none is given: per row, the one of the five filters whose residuals look
        /// cheapest — with Huffman, an estimate of their bits on pairs of 8-byte words (one pair in
        /// <see cref="PngWordFilter.SampleEvery"/> words, every other row; <see cref="PngWordFilter.Choose"/>); with
        /// DeflateStream, the smallest sum of |residual| over every byte.
        /// </summary>
        public const PngFilter DefaultFilter = PngFilter.Adaptive;

        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        // Filtered rows are handed to DEFLATE in batches of about this size: fewer calls into zlib than one per row.
        const int BatchBytes = 1 << 16;

        sealed class Scratch
        {
            public readonly GrowableBuffer Output = new GrowableBuffer();
            public byte[] Batch = new byte[BatchBytes];
            public byte[] Row = new byte[0];
            public byte[] PreviousRow = new byte[0];
            public byte[] Zeros = new byte[0];
            public ulong[] WordRow = new ulong[0];
            public ulong[] WordRowAbove = new ulong[0];
            public ulong[] Filtered = new ulong[0];
            public readonly HuffmanDeflate Deflate = new HuffmanDeflate();
            public readonly Lz77Deflate Lz77 = new Lz77Deflate();
            public byte[] Stream = new byte[0];
        }

        [ThreadStatic] static Scratch scratch;

        /// <summary>
        /// Encodes tightly packed pixels, top row first. For <see cref="PngPixelFormat.Gray16"/> each sample is two
        /// bytes, big-endian (most significant first), as PNG stores it; use <see cref="EncodeGray16"/> for ushorts.
        /// </summary>
        public static byte[] Encode(byte[] pixels, int width, int height, PngPixelFormat format,
            PngCompression compression = DefaultCompression, PngFilter filter = DefaultFilter)
        {
            Validate(pixels?.Length, "pixels", width, height, format, compression, filter, BytesPerPixel(format));
            return EncodeCore(pixels, null, width, height, format, compression, filter);
        }

        /// <summary>Encodes 16-bit gray samples (e.g. depth in millimetres), top row first.</summary>
        public static byte[] EncodeGray16(ushort[] samples, int width, int height,
            PngCompression compression = DefaultCompression, PngFilter filter = DefaultFilter)
        {
            Validate(samples?.Length, "samples", width, height, PngPixelFormat.Gray16, compression, filter, 1);
            return EncodeCore(null, samples, width, height, PngPixelFormat.Gray16, compression, filter);
        }

        public static int BytesPerPixel(PngPixelFormat format)
        {
            switch (format)
            {
                case PngPixelFormat.Gray8: return 1;
                case PngPixelFormat.Rgb8: return 3;
                case PngPixelFormat.Rgba8: return 4;
                case PngPixelFormat.Gray16: return 2;
                default: throw new ArgumentOutOfRangeException(nameof(format), format, "Use Gray8, Rgb8, Rgba8 or Gray16.");
            }
        }

        static void Validate(int? length, string field, int width, int height, PngPixelFormat format, PngCompression compression, PngFilter filter, int elementsPerPixel)
        {
            InvalidParameterException.ThrowIfAny(
                ValidationProblem.OutsideRange("width", width, 1, MaxDimension),
                ValidationProblem.OutsideRange("height", height, 1, MaxDimension));
            if (compression < PngCompression.Fastest || compression > PngCompression.Lz77)
                throw new ArgumentOutOfRangeException(nameof(compression), compression, "Use Lz77, Huffman, Fastest, Optimal or None.");
            if (filter < PngFilter.None || filter > PngFilter.Adaptive)
                throw new ArgumentOutOfRangeException(nameof(filter), filter, "Use None, Sub, Up, Average, Paeth or Adaptive.");
            long rowBytes = (long)width * BytesPerPixel(format);
            if (rowBytes + 1 > int.MaxValue / 4)
                throw new InvalidParameterException(new[] { new ValidationProblem("width", width.ToString(System.Globalization.CultureInfo.InvariantCulture), "makes a row too long to encode.", "Use a smaller width.") });
            long expected = (long)width * height * elementsPerPixel;
            if (length == null || length.Value != expected)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(field, length == null ? "null" : "length " + length.Value.ToString(System.Globalization.CultureInfo.InvariantCulture),
                        $"does not match {width}×{height} {format} (expected {expected.ToString(System.Globalization.CultureInfo.InvariantCulture)}).",
                        "Pass exactly width × height pixels, tightly packed, top row first.")
                });
        }

        /// <summary>Largest width or height accepted (PNG allows 2^31 − 1; this keeps a row and the file within an array).</summary>
        public const int MaxDimension = 1 << 20;

        static byte[] EncodeCore(byte[] pixels, ushort[] samples, int width, int height, PngPixelFormat format,
            PngCompression compression, PngFilter filter)
        {
            var s = scratch ?? (scratch = new Scratch());
            int bpp = BytesPerPixel(format);
            int rowBytes = width * bpp;
            EnsureRows(s, rowBytes);
            // The Huffman path holds the whole filtered image and reads bytes as little-endian words; beyond an
            // array's reach (or on a big-endian machine, which Unity's editor never is), DeflateStream streams it.
            bool ours = compression == PngCompression.Huffman || compression == PngCompression.Lz77;
            if (ours && (long)(rowBytes + 1) * height <= MaxHuffmanBytes && BitConverter.IsLittleEndian)
            {
                FilterIntoWords(s, pixels, samples, width, height, format, filter);
                return compression == PngCompression.Huffman ? EncodeHuffman(s, width, height, format) : EncodeLz77(s, width, height, format);
            }
            if (ours) compression = PngCompression.Optimal;
            if (s.Batch.Length < rowBytes + 1) s.Batch = new byte[rowBytes + 1];

            var output = s.Output;
            output.Reset();
            output.Write(Signature, 0, Signature.Length);
            WriteHeader(output, width, height, format);

            // IDAT: length (patched below), type, zlib header, DEFLATE data, Adler-32, CRC.
            int idatStart = output.Reserve(8);
            PutType(output.Array, idatStart + 4, "IDAT");
            int zlibHeader = output.Reserve(2);
            output.Array[zlibHeader] = 0x78; // CM = 8 (deflate), CINFO = 7 (32 KiB window)
            output.Array[zlibHeader + 1] = ZlibFlags(compression);

            uint adler = Adler32.Start;
            using (var deflate = new DeflateStream(output, ToLevel(compression), leaveOpen: true))
            {
                byte[] batch = s.Batch;
                int filled = 0;
                for (int y = 0; y < height; y++)
                {
                    SelectRow(s, pixels, samples, y, width, rowBytes, out var src, out var srcOffset, out var prev, out var prevOffset);
                    if (filled + rowBytes + 1 > batch.Length)
                    {
                        adler = Adler32.Update(adler, batch, 0, filled);
                        deflate.Write(batch, 0, filled);
                        filled = 0;
                    }
                    int type = filter == PngFilter.Adaptive
                        ? PngRowFilter.ChooseMinimumSum(src, srcOffset, prev, prevOffset, rowBytes, bpp)
                        : (int)filter;
                    PngRowFilter.Apply(type, src, srcOffset, prev, prevOffset, rowBytes, bpp, batch, filled);
                    filled += rowBytes + 1;
                }
                adler = Adler32.Update(adler, batch, 0, filled);
                deflate.Write(batch, 0, filled);
            }

            int adlerAt = output.Reserve(4);
            PutUInt32(output.Array, adlerAt, adler);
            int idatLength = (int)output.Length - idatStart - 8;
            PutUInt32(output.Array, idatStart, (uint)idatLength);
            FinishChunk(output, idatStart);

            int iend = output.Reserve(8);
            PutUInt32(output.Array, iend, 0);
            PutType(output.Array, iend + 4, "IEND");
            FinishChunk(output, iend);

            var file = new byte[output.Length];
            Buffer.BlockCopy(output.Array, 0, file, 0, file.Length);
            return file;
        }

        // The filtered image is held whole, as ulong words, and the file is one array: 1 GiB of rows keeps both well
        // inside an array's 2 GB (stored blocks add 5 bytes per 65 535). An 8192² RGBA image is 256 MiB.
        const long MaxHuffmanBytes = 1L << 30;

        /// <summary>
        /// Copies each row into 64-bit words, filters it there (<see cref="PngWordFilter"/>) and places it with its
        /// type byte in the thread's <see cref="HuffmanDeflate"/> stream.
        /// </summary>
        static void FilterIntoWords(Scratch s, byte[] pixels, ushort[] samples, int width, int height, PngPixelFormat format, PngFilter filter)
        {
            int bpp = BytesPerPixel(format);
            int rowBytes = width * bpp;
            var deflate = s.Deflate;
            deflate.Begin(bpp, rowBytes, height);
            int rowWords = deflate.RowWords;
            if (s.WordRow.Length < rowWords)
            {
                s.WordRow = new ulong[rowWords];
                s.WordRowAbove = new ulong[rowWords];
                s.Filtered = new ulong[rowWords];
            }
            ulong[] row = s.WordRow, above = s.WordRowAbove, filtered = s.Filtered;
            Array.Clear(above, 0, rowWords);
            int shift = 8 * bpp;
            int type = 0;
            for (int y = 0; y < height; y++)
            {
                row[rowWords - 1] = 0; // the padding past the row's end
                if (pixels != null) Buffer.BlockCopy(pixels, y * rowBytes, row, 0, rowBytes);
                else
                {
                    Buffer.BlockCopy(samples, y * rowBytes, row, 0, rowBytes);
                    PngWordFilter.SwapBytePairs(row, rowWords);
                }
                // Adaptive: a row's neighbours are alike, so every odd row takes the type chosen for the row above
                // (half the estimates; the benchmark's files within −0.2…+1.8 % of choosing every row), unless that
                // was None, which may be the background above an object's first row.
                if (filter != PngFilter.Adaptive) type = (int)filter;
                else if ((y & 1) == 0 || type == 0) type = PngWordFilter.Choose(row, above, rowWords, shift);
                PngWordFilter.Apply(type, row, above, rowWords, shift, filtered, 0);
                deflate.PutRow(y, type, filtered);
                var swap = above;
                above = row;
                row = swap;
            }
            s.WordRow = row;
            s.WordRowAbove = above;
        }

        /// <summary>Writes the file array in one go: its exact size is known once the codes are built.</summary>
        static byte[] EncodeHuffman(Scratch s, int width, int height, PngPixelFormat format)
        {
            var deflate = s.Deflate;
            int deflateBytes = deflate.Compress(out uint adler);
            var file = NewFile(width, height, format, PngCompression.Huffman, deflateBytes, out int idat, out int idatData);
            deflate.Write(file, idat + 10);
            return FinishFile(file, idat, idatData, adler);
        }

        /// <summary>
        /// A file array of the exact size for one IDAT of <paramref name="deflateBytes"/>, with the signature, IHDR, the
        /// IDAT's length, type and zlib header written; the DEFLATE data goes at <c>idat + 10</c>, then <see cref="FinishFile"/>.
        /// </summary>
        static byte[] NewFile(int width, int height, PngPixelFormat format, PngCompression compression, int deflateBytes, out int idat, out int idatData)
        {
            const int headerBytes = 8 + 12 + 13;
            idatData = 2 + deflateBytes + 4;
            var file = new byte[headerBytes + 12 + idatData + 12];
            Buffer.BlockCopy(Signature, 0, file, 0, Signature.Length);
            WriteHeader(file, 8, width, height, format);
            idat = headerBytes;
            PutUInt32(file, idat, (uint)idatData);
            PutType(file, idat + 4, "IDAT");
            file[idat + 8] = 0x78;
            file[idat + 9] = ZlibFlags(compression);
            return file;
        }

        /// <summary>
        /// The zlib payload (already laid out in the thread's <see cref="HuffmanDeflate"/> stream: each row's type
        /// byte, then its bytes) compressed by <see cref="Lz77Deflate"/>.
        /// </summary>
        static byte[] EncodeLz77(Scratch s, int width, int height, PngPixelFormat format)
        {
            int length = s.Deflate.StreamBytes;
            if (s.Stream.Length < length) s.Stream = new byte[length];
            byte[] stream = s.Stream;
            Buffer.BlockCopy(s.Deflate.Stream, 0, stream, 0, length);
            uint adler = Adler32.Compute(stream, 0, length);
            int deflateBytes = s.Lz77.Compress(stream, length);
            var file = NewFile(width, height, format, PngCompression.Lz77, deflateBytes, out int idat, out int idatData);
            Buffer.BlockCopy(s.Lz77.Output, 0, file, idat + 10, deflateBytes);
            return FinishFile(file, idat, idatData, adler);
        }

        /// <summary>The Adler-32 after the DEFLATE data, the IDAT's CRC and the IEND chunk.</summary>
        static byte[] FinishFile(byte[] file, int idat, int idatData, uint adler)
        {
            PutUInt32(file, idat + 4 + idatData, adler);
            PutUInt32(file, idat + 8 + idatData, Crc32.Compute(file, idat + 4, 4 + idatData));
            int iend = idat + 12 + idatData;
            PutUInt32(file, iend, 0);
            PutType(file, iend + 4, "IEND");
            PutUInt32(file, iend + 8, Crc32.Compute(file, iend + 4, 4));
            return file;
        }

        /// <summary>Row y's bytes and the row above (zeros for the first row); ushort samples become big-endian byte rows.</summary>
        static void SelectRow(Scratch s, byte[] pixels, ushort[] samples, int y, int width, int rowBytes,
            out byte[] src, out int srcOffset, out byte[] prev, out int prevOffset)
        {
            if (pixels != null)
            {
                src = pixels;
                srcOffset = y * rowBytes;
                prev = y == 0 ? s.Zeros : pixels;
                prevOffset = y == 0 ? 0 : srcOffset - rowBytes;
                return;
            }
            // The previous row is kept for Up/Average/Paeth.
            byte[] swap = s.PreviousRow;
            s.PreviousRow = s.Row;
            s.Row = swap;
            ToBigEndian(samples, y * width, width, s.Row);
            src = s.Row;
            srcOffset = 0;
            prev = y == 0 ? s.Zeros : s.PreviousRow;
            prevOffset = 0;
        }

        static void EnsureRows(Scratch s, int rowBytes)
        {
            if (s.Zeros.Length < rowBytes)
            {
                s.Zeros = new byte[rowBytes];
                s.Row = new byte[rowBytes];
                s.PreviousRow = new byte[rowBytes];
            }
        }

        static void ToBigEndian(ushort[] samples, int first, int count, byte[] row)
        {
            for (int i = 0, o = 0; i < count; i++, o += 2)
            {
                ushort v = samples[first + i];
                row[o] = (byte)(v >> 8);
                row[o + 1] = (byte)v;
            }
        }

        static void WriteHeader(GrowableBuffer output, int width, int height, PngPixelFormat format)
        {
            int at = output.Reserve(8 + 13 + 4);
            WriteHeader(output.Array, at, width, height, format);
        }

        /// <summary>The whole IHDR chunk, CRC included (25 bytes), at <paramref name="at"/>.</summary>
        static void WriteHeader(byte[] b, int at, int width, int height, PngPixelFormat format)
        {
            PutUInt32(b, at, 13);
            PutType(b, at + 4, "IHDR");
            PutUInt32(b, at + 8, (uint)width);
            PutUInt32(b, at + 12, (uint)height);
            b[at + 16] = (byte)(format == PngPixelFormat.Gray16 ? 16 : 8);
            b[at + 17] = (byte)(format == PngPixelFormat.Rgb8 ? 2 : format == PngPixelFormat.Rgba8 ? 6 : 0);
            b[at + 18] = 0; // compression method: deflate
            b[at + 19] = 0; // filter method: adaptive (the five types)
            b[at + 20] = 0; // no interlace
            PutUInt32(b, at + 21, Crc32.Compute(b, at + 4, 17));
        }

        /// <summary>Appends the CRC of the chunk that starts (at its length field) at <paramref name="chunkStart"/> and runs to the end.</summary>
        static void FinishChunk(GrowableBuffer output, int chunkStart)
        {
            int end = (int)output.Length;
            uint crc = Crc32.Compute(output.Array, chunkStart + 4, end - chunkStart - 4);
            int at = output.Reserve(4);
            PutUInt32(output.Array, at, crc);
        }

        // RFC 1950: FLEVEL (bits 6–7) records the effort; FCHECK makes (CMF·256 + FLG) a multiple of 31.
        static byte ZlibFlags(PngCompression compression)
        {
            // Optimal: "default" (2); Lz77: "fast" (1); Huffman, Fastest and None: "fastest" (0).
            int level = compression == PngCompression.Optimal ? 2 : compression == PngCompression.Lz77 ? 1 : 0;
            int flags = level << 6;
            flags += 31 - (0x78 * 256 + flags) % 31;
            return (byte)flags;
        }

        static CompressionLevel ToLevel(PngCompression compression)
        {
            switch (compression)
            {
                case PngCompression.Fastest: return CompressionLevel.Fastest;
                case PngCompression.Optimal: return CompressionLevel.Optimal;
                case PngCompression.None: return CompressionLevel.NoCompression;
                default: throw new ArgumentOutOfRangeException(nameof(compression), compression, "Use Huffman, Fastest, Optimal or None.");
            }
        }

        static void PutUInt32(byte[] b, int at, uint v)
        {
            b[at] = (byte)(v >> 24);
            b[at + 1] = (byte)(v >> 16);
            b[at + 2] = (byte)(v >> 8);
            b[at + 3] = (byte)v;
        }

        static void PutType(byte[] b, int at, string type)
        {
            for (int i = 0; i < 4; i++) b[at + i] = (byte)type[i];
        }
    }
}
