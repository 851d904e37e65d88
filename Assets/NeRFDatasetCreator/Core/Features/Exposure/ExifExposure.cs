using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A minimal Exif block (a little-endian TIFF structure, CIPA DC-008 / Exif 2.32) that states a view's exposure as a
    /// camera would: ExposureTime t, FNumber N and PhotographicSensitivity (ISO) S with log2(t · S / N²) = EV, the
    /// "relative exposure" gsplat's <c>compute_exposure_from_exif</c> computes (examples/exif.py:94–121). N = 4 and
    /// S = 1600 are fixed and t = 2^EV / 100 s (1/100 s at EV 0), so the EV is held by the shutter time alone. The block
    /// goes into the PNG's <c>eXIf</c> chunk (<see cref="PngChunks.InsertExif"/>).
    /// </summary>
    public static class ExifExposure
    {
        public const double FNumber = 4;
        public const int Iso = 1600;
        /// <summary>The shutter time at EV 0, in seconds: t = 2^EV · this, so that t · ISO / N² = 2^EV.</summary>
        public const double SecondsAtZero = FNumber * FNumber / Iso;

        const ushort TagExifIfd = 34665, TagExposureTime = 33434, TagFNumber = 33437, TagIso = 34855;
        const ushort TypeShort = 3, TypeLong = 4, TypeRational = 5;

        /// <summary>The shutter time in seconds for <paramref name="ev"/>.</summary>
        public static double ExposureTime(double ev) => Math.Pow(2, ev) * SecondsAtZero;

        /// <summary>The Exif block ("II*\0" …) for a view exposed at <paramref name="ev"/> stops.</summary>
        public static byte[] Block(double ev)
        {
            if (double.IsNaN(ev) || Math.Abs(ev) > 30) throw new ArgumentOutOfRangeException(nameof(ev), ev, "an exposure in stops, |EV| ≤ 30");
            var (num, den) = Rational(ExposureTime(ev));
            // Layout: header (8) | IFD0: count, 1 entry, next = 0 (2 + 12 + 4) | Exif IFD: count, 3 entries, next = 0 (2 + 36 + 4)
            // | ExposureTime rational (8) | FNumber rational (8).
            const int ifd0 = 8, exifIfd = ifd0 + 2 + 12 + 4, values = exifIfd + 2 + 3 * 12 + 4;
            var b = new byte[values + 16];
            b[0] = (byte)'I'; b[1] = (byte)'I'; U16(b, 2, 42); U32(b, 4, ifd0);
            U16(b, ifd0, 1);
            Entry(b, ifd0 + 2, TagExifIfd, TypeLong, 1, exifIfd);
            U32(b, ifd0 + 14, 0);
            U16(b, exifIfd, 3); // entries in ascending tag order, as TIFF requires
            Entry(b, exifIfd + 2, TagExposureTime, TypeRational, 1, values);
            Entry(b, exifIfd + 14, TagFNumber, TypeRational, 1, values + 8);
            Entry(b, exifIfd + 26, TagIso, TypeShort, 1, Iso); // a SHORT sits in the value field's first two bytes
            U32(b, exifIfd + 38, 0);
            U32(b, values, num); U32(b, values + 4, den);
            U32(b, values + 8, (uint)FNumber); U32(b, values + 12, 1);
            return b;
        }

        /// <summary>
        /// t as num/den in 32-bit unsigned integers with the largest denominator that keeps num in range: num ≥ t · 2^32 / 2,
        /// so at EV −10 (t ≈ 9.8 µs, num ≈ 41 943) the rounding moves log2(t) by at most 1.8·10⁻⁵ stops, and less above.
        /// </summary>
        public static (uint num, uint den) Rational(double seconds)
        {
            var den = seconds <= 1 ? uint.MaxValue : Math.Floor(uint.MaxValue / seconds);
            var num = Math.Round(seconds * den);
            if (num < 1) num = 1;
            if (num > uint.MaxValue) num = uint.MaxValue;
            return ((uint)num, (uint)den);
        }

        static void Entry(byte[] b, int at, ushort tag, ushort type, uint count, uint value)
        {
            U16(b, at, tag); U16(b, at + 2, type); U32(b, at + 4, count); U32(b, at + 8, value);
        }

        static void U16(byte[] b, int at, int v) { b[at] = (byte)v; b[at + 1] = (byte)(v >> 8); }

        static void U32(byte[] b, int at, uint v)
        {
            b[at] = (byte)v; b[at + 1] = (byte)(v >> 8); b[at + 2] = (byte)(v >> 16); b[at + 3] = (byte)(v >> 24);
        }

        internal static string Describe(double ev) => ExposureTime(ev).ToString("R", CultureInfo.InvariantCulture) + " s, f/4, ISO 1600";
    }
}
