using System;

namespace NerfDatasetCreator
{
    /// <summary>Adds ancillary chunks to an encoded PNG without re-encoding it.</summary>
    public static class PngChunks
    {
        // Signature (8) + IHDR: length (4), type (4), 13 data bytes, CRC (4).
        const int AfterHeader = 8 + 4 + 4 + 13 + 4;

        /// <summary>
        /// The PNG with an <c>eXIf</c> chunk holding <paramref name="exif"/> (a TIFF structure, "II*\0" or "MM\0*") right
        /// after IHDR: the PNG specification orders eXIf before IDAT, which is also where Pillow reads it on open
        /// (PngImagePlugin's chunk_eXIf sets <c>info["exif"]</c>).
        /// </summary>
        public static byte[] InsertExif(byte[] png, byte[] exif)
        {
            if (png == null || png.Length < AfterHeader || png[12] != 'I' || png[13] != 'H' || png[14] != 'D' || png[15] != 'R')
                throw new ArgumentException("not a PNG that starts with its IHDR chunk", nameof(png));
            if (exif == null || exif.Length < 8) throw new ArgumentException("an Exif block starts with an 8-byte TIFF header", nameof(exif));
            var chunk = 12 + exif.Length;
            var result = new byte[png.Length + chunk];
            Buffer.BlockCopy(png, 0, result, 0, AfterHeader);
            var at = AfterHeader;
            Put32(result, at, (uint)exif.Length);
            result[at + 4] = (byte)'e'; result[at + 5] = (byte)'X'; result[at + 6] = (byte)'I'; result[at + 7] = (byte)'f';
            Buffer.BlockCopy(exif, 0, result, at + 8, exif.Length);
            Put32(result, at + 8 + exif.Length, Crc32.Compute(result, at + 4, 4 + exif.Length));
            Buffer.BlockCopy(png, AfterHeader, result, AfterHeader + chunk, png.Length - AfterHeader);
            return result;
        }

        static void Put32(byte[] b, int at, uint v)
        {
            b[at] = (byte)(v >> 24); b[at + 1] = (byte)(v >> 16); b[at + 2] = (byte)(v >> 8); b[at + 3] = (byte)v;
        }
    }
}
