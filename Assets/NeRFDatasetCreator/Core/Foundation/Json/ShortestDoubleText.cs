using System;
using System.Numerics;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The text .NET Core 3.0+ gives a double with <c>ToString("R", CultureInfo.InvariantCulture)</c> — the fewest
    /// significant digits that read back to the same double, the closest such digits to the exact value — written
    /// the same on every runtime, without formatting or parsing through the runtime. Mono (Unity's runtime) formats
    /// "R" as .NET Framework did: 15 digits when they read back, else 17 even where 16 suffice (58 % of random
    /// doubles), so files written in Unity would differ from the command-line tool's; and the runtime's formatting
    /// allocates a string per number, which a 300 000-view transforms file writes 4.8 million times.
    /// </summary>
    /// <remarks>
    /// Why testing three lengths suffices: a normal double has 15 significant digits of precision, so at most one
    /// decimal of 15 or fewer digits lies within its rounding interval (15-digit decimals are more than an interval
    /// apart); when one does, rounding the exact value to 15 digits gives it (padded with zeros, which are dropped).
    /// Otherwise the answer has 16 or 17 digits, and at each length the only decimals that can lie in the interval are
    /// the two neighbours of the exact value at that length; at 17 digits one always does. So: for n = 15, 16, 17, take
    /// the exact value's two n-digit neighbours; the first length with a neighbour inside the interval wins, the closer
    /// neighbour when both are inside, the even last digit on an exact tie. The interval reaches half an ulp each side
    /// (a quarter below a power of two, whose lower neighbour is closer) and holds its ends when the double's last bit
    /// is even (they read back to it under ties-to-even), as .NET's own formatter has it. Subnormals have fewer digits
    /// of precision and try every length from 1. The exact value × 10^k is computed in 128-bit integer arithmetic for
    /// 1e-8 ≲ |v| &lt; 1e15 (the poses and intrinsics of a plan), in a 192-bit product near zero and with
    /// <see cref="BigInteger"/> elsewhere. .NET 10's "R" differs only at 2^-25 and 2^-958, where its shorter text reads
    /// back as the double below (it takes the full half ulp below a power of two); the text here reads back. Tests
    /// compare with .NET's "R" on millions of random and edge doubles, and check with exact rationals on any runtime.
    /// </remarks>
    public static class ShortestDoubleText
    {
        /// <summary>Characters <see cref="WriteJson"/> may need: sign, 17 digits, point, "0.000" and an exponent "e-324".</summary>
        public const int MaxLength = 32;

        /// <summary>
        /// Writes <paramref name="value"/> (finite) as the dataset files' JSON number — .NET's "R" text with a lowercase
        /// exponent and ".0" on whole numbers, "0.0" for both zeros — into <paramref name="buffer"/> at
        /// <paramref name="at"/>; returns the index after the last character.
        /// </summary>
        public static int WriteJson(double value, char[] buffer, int at)
        {
            if (value - value != 0) // NaN or infinity: JSON cannot hold them
                throw new ArgumentException("A dataset file cannot hold " + value.ToString(System.Globalization.CultureInfo.InvariantCulture) + ": it is not valid JSON.", nameof(value));
            if (value == 0)
            {
                buffer[at] = '0';
                buffer[at + 1] = '.';
                buffer[at + 2] = '0';
                return at + 3;
            }
            if (value < 0)
            {
                buffer[at++] = '-';
                value = -value;
            }
            Shortest(value, out var digits, out var count, out var scale);
            return Layout(digits, count, scale, buffer, at);
        }

        /// <summary><see cref="WriteJson"/> as a string.</summary>
        public static string Json(double value)
        {
            var buffer = new char[MaxLength];
            return new string(buffer, 0, WriteJson(value, buffer, 0));
        }

        // .NET's "R" lays out the digits as "G17" does: scientific when the decimal point would sit more than 17
        // places right of the first digit (1E+17, but 10000000000000000) or more than three zeros left of it (1E-05,
        // but 0.0001), with an exponent of at least two digits.
        static int Layout(ulong digits, int count, int scale, char[] b, int at)
        {
            if (scale > 17 || scale < -3)
            {
                WriteDigits(digits, b, at, count);
                var end = at + count;
                if (count > 1) end = InsertPoint(b, at + 1, end);
                b[end++] = 'e';
                var exponent = scale - 1;
                b[end++] = exponent < 0 ? '-' : '+';
                if (exponent < 0) exponent = -exponent;
                if (exponent >= 100) b[end++] = (char)('0' + exponent / 100);
                b[end++] = (char)('0' + exponent / 10 % 10);
                b[end++] = (char)('0' + exponent % 10);
                return end;
            }
            if (scale <= 0)
            {
                b[at++] = '0';
                b[at++] = '.';
                for (var i = scale; i < 0; i++) b[at++] = '0';
                WriteDigits(digits, b, at, count);
                return at + count;
            }
            WriteDigits(digits, b, at, count);
            if (scale < count) return InsertPoint(b, at + scale, at + count);
            at += count;
            for (var i = count; i < scale; i++) b[at++] = '0';
            b[at++] = '.';
            b[at++] = '0';
            return at;
        }

        // Moves b[point..end) one place right and puts the decimal point at point; returns the new end.
        static int InsertPoint(char[] b, int point, int end)
        {
            for (var i = end; i > point; i--) b[i] = b[i - 1];
            b[point] = '.';
            return end + 1;
        }

        static readonly char[] Pairs = DigitPairs();

        static char[] DigitPairs()
        {
            var pairs = new char[200];
            for (var i = 0; i < 100; i++)
            {
                pairs[2 * i] = (char)('0' + i / 10);
                pairs[2 * i + 1] = (char)('0' + i % 10);
            }
            return pairs;
        }

        // The count (≤ 17) digits at b[first..first + count), two at a time and in 32-bit arithmetic below the top 8:
        // Mono divides a 64-bit number by 10 with a real division, which made this half of the formatter's time there.
        static void WriteDigits(ulong digits, char[] b, int first, int count)
        {
            var at = first + count;
            var pairs = Pairs;
            if (count > 8)
            {
                var high = digits / 100000000UL;
                var low = (uint)(digits - high * 100000000UL);
                for (var i = 0; i < 4; i++)
                {
                    var next = low / 100;
                    var r = (int)(low - next * 100) * 2;
                    b[--at] = pairs[r + 1];
                    b[--at] = pairs[r];
                    low = next;
                }
                digits = high;
                count -= 8;
            }
            var rest = (uint)digits;
            for (; count >= 2; count -= 2)
            {
                var next = rest / 100;
                var r = (int)(rest - next * 100) * 2;
                b[--at] = pairs[r + 1];
                b[--at] = pairs[r];
                rest = next;
            }
            if (count == 1) b[--at] = (char)('0' + rest);
        }

        static readonly ulong[] Pow10 =
        {
            1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000, 10000000000, 100000000000,
            1000000000000, 10000000000000, 100000000000000, 1000000000000000, 10000000000000000, 100000000000000000,
        };

        const int MaxFastPower = 26; // 5^26 < 2^61
        const int MaxFastShift = 55; // keeps 100 × 2^(shift + 2) below 2^64

        static readonly ulong[] Pow5 = Powers5();

        static ulong[] Powers5()
        {
            var p = new ulong[MaxFastPower + 1];
            p[0] = 1;
            for (var i = 1; i < p.Length; i++) p[i] = p[i - 1] * 5;
            return p;
        }

        /// <summary>The shortest digits of a finite positive <paramref name="value"/>: value = 0.digits × 10^scale.</summary>
        public static void Shortest(double value, out ulong digits, out int count, out int scale)
        {
            var bits = BitConverter.DoubleToInt64Bits(value);
            var biased = (int)(bits >> 52) & 0x7FF;
            var f = (ulong)bits & 0xFFFFFFFFFFFFFUL;
            int e;
            if (biased == 0) e = -1074;
            else
            {
                f |= 1UL << 52;
                e = biased - 1075;
            }
            // The double below a power of two is half as far as the one above: the interval's lower half is halved.
            var lowerHalved = f == 1UL << 52 && biased > 1;
            // An end of the interval reads back as this double when its last bit is even (ties to even): .NET accepts it then.
            var ends = (f & 1) == 0;
            var log2 = biased != 0 ? e + 52 : e + 63 - LeadingZeros(f); // floor(log2 value)
            var k = 16 - ((log2 * 78913) >> 18); // 78913 / 2^18 ≈ log10 2: floor(log10 value) or one less
            if (FastDigits(f, e, k, lowerHalved, ends, out digits, out count, out scale)) return;
            if (WideDigits(f, e, k, lowerHalved, out digits, out count, out scale)) return;
            ExactDigits(f, e, k, lowerHalved, ends, biased == 0 ? 1 : 15, out digits, out count, out scale);
        }

        // value × 10^k = f × 5^k / 2^s with s = -(e + k), as a 128-bit integer (hi, lo) split at bit s. All distances
        // below are in units of 2^-(s + 2) of the 17th digit, so the half-ulp margins 5^k / 2^(s+1) are whole numbers.
        static bool FastDigits(ulong f, int e, int k, bool lowerHalved, bool ends, out ulong digits, out int count, out int scale)
        {
            digits = 0;
            count = 0;
            scale = 0;
            for (var attempt = 0; attempt < 3; attempt++)
            {
                var s = -(e + k);
                if (k < 0 || k > MaxFastPower || s < 1 || s > MaxFastShift) return false;
                var p = Pow5[k];
                ulong fl = f & 0xFFFFFFFFUL, fh = f >> 32, pl = p & 0xFFFFFFFFUL, ph = p >> 32;
                var mid = fh * pl + fl * ph; // < 2^62
                var low = fl * pl;
                var lo = low + (mid << 32);
                var hi = fh * ph + (mid >> 32) + (lo < low ? 1UL : 0UL);
                var d = (hi << (64 - s)) | (lo >> s);
                if (d >= Pow10[17] || d < Pow10[16])
                {
                    k += d < Pow10[16] ? 1 : -1; // the estimate of the decimal exponent was one off
                    continue;
                }
                var fraction = (lo & ((1UL << s) - 1)) << 2;
                var one = 1UL << (s + 2);
                var high = p << 1;
                var lowMargin = lowerHalved ? p : high;
                for (var n = 15; n <= 17; n++)
                {
                    var unit = Pow10[17 - n];
                    var q = n == 15 ? d / 100 : n == 16 ? d / 10 : d; // divisions by constants: multiplications
                    var below = (d - q * unit) * one + fraction; // distance down to the neighbour q
                    var above = unit * one - below;               // distance up to q + 1
                    var pick = Pick(below < lowMargin || (ends && below == lowMargin), above < high || (ends && above == high), below < above ? -1 : below > above ? 1 : 0, q);
                    if (pick < 0) continue;
                    Finish((ulong)pick, n, 17 - k, out digits, out count, out scale);
                    return true;
                }
                break; // cannot happen (see the remarks): the exact path decides
            }
            return false;
        }

        const int MaxWidePower = 55; // 5^55 < 2^128
        static readonly ulong[] Pow5High = new ulong[MaxWidePower + 1], Pow5Low = new ulong[MaxWidePower + 1];

        static ShortestDoubleText()
        {
            for (var i = 0; i <= MaxWidePower; i++)
            {
                var p = BigInteger.Pow(5, i);
                Pow5High[i] = (ulong)(p >> 64);
                Pow5Low[i] = (ulong)(p & ulong.MaxValue);
            }
        }

        // The numbers near zero a pose holds (a rotation entry of 1e-17 where an exact one would be 0: 4 % of a plan's
        // numbers) and whatever else has 5^k below 2^128 and a shift below 128: value × 10^k = f × 5^k / 2^s as a
        // 192-bit product, its 17 digits exact, the fraction below them to 64 bits. The comparisons with the interval
        // are made in doubles (error below 1e-14 of a 17th-digit unit); where two sides come within 1e-9 of each other
        // — exact ties and interval ends among them, never seen in the tests' millions of values — the exact path decides.
        static bool WideDigits(ulong f, int e, int k, bool lowerHalved, out ulong digits, out int count, out int scale)
        {
            digits = 0;
            count = 0;
            scale = 0;
            for (var attempt = 0; attempt < 3; attempt++)
            {
                var s = -(e + k);
                if (k < 0 || k > MaxWidePower || s < 1 || s > 127) return false;
                Multiply(f, Pow5Low[k], out var c1, out var n0);
                Multiply(f, Pow5High[k], out var d1, out var d0);
                var n1 = c1 + d0;
                var n2 = d1 + (n1 < c1 ? 1UL : 0UL);
                ulong d, fraction;
                if (s < 64)
                {
                    d = (n1 << (64 - s)) | (n0 >> s);
                    fraction = n0 << (64 - s);
                }
                else if (s == 64)
                {
                    d = n1;
                    fraction = n0;
                }
                else
                {
                    var t = s - 64;
                    d = (n2 << (64 - t)) | (n1 >> t);
                    fraction = (n1 << (64 - t)) | (n0 >> t);
                }
                if (d >= Pow10[17] || d < Pow10[16])
                {
                    k += d < Pow10[16] ? 1 : -1;
                    continue;
                }
                var x = fraction * TwoToMinus64;
                var high = (Pow5High[k] * TwoTo64 + Pow5Low[k]) * PowerOfTwo(-(s + 1)); // half an ulp in 17th-digit units
                var lowMargin = lowerHalved ? high * 0.5 : high;
                for (var n = 15; n <= 17; n++)
                {
                    var unit = Pow10[17 - n];
                    var q = d / unit;
                    var below = (d - q * unit) + x;
                    var above = unit - below;
                    if (Near(below, lowMargin) || Near(above, high) || Near(below, above)) return false;
                    var pick = Pick(below < lowMargin, above < high, below < above ? -1 : 1, q);
                    if (pick < 0) continue;
                    Finish((ulong)pick, n, 17 - k, out digits, out count, out scale);
                    return true;
                }
                return false;
            }
            return false;
        }

        const double TwoTo64 = 18446744073709551616.0;
        const double TwoToMinus64 = 1.0 / 18446744073709551616.0;

        static bool Near(double a, double b) => Math.Abs(a - b) < 1e-9;

        static double PowerOfTwo(int exponent) => BitConverter.Int64BitsToDouble((long)(exponent + 1023) << 52); // normal exponents only

        // a × b as a 128-bit (high, low), in 32-bit halves.
        static void Multiply(ulong a, ulong b, out ulong high, out ulong low)
        {
            ulong a0 = a & 0xFFFFFFFFUL, a1 = a >> 32, b0 = b & 0xFFFFFFFFUL, b1 = b >> 32;
            ulong p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0;
            var mid = (p00 >> 32) + (p01 & 0xFFFFFFFFUL) + (p10 & 0xFFFFFFFFUL);
            low = (mid << 32) | (p00 & 0xFFFFFFFFUL);
            high = a1 * b1 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
        }

        // The same steps in exact rational arithmetic, for the values outside the fast path's range.
        static void ExactDigits(ulong f, int e, int k, bool lowerHalved, bool ends, int shortest, out ulong digits, out int count, out int scale)
        {
            for (var attempt = 0; attempt < 3; attempt++)
            {
                // value × 10^k = num / den; one unit of the last bit (an ulp) × 10^k = ulp / den.
                var ulp = BigInteger.One;
                var den = BigInteger.One;
                if (e >= 0) ulp <<= e;
                else den <<= -e;
                if (k >= 0) ulp *= BigInteger.Pow(10, k);
                else den *= BigInteger.Pow(10, -k);
                var d = BigInteger.DivRem(f * ulp, den, out var rest);
                if (d >= Pow10[17] || d < Pow10[16])
                {
                    k += d < Pow10[16] ? 1 : -1;
                    continue;
                }
                // Units of 1 / (4 den): the 17th digit is 4 den, the margins half an ulp (2 ulp) or a quarter (ulp).
                var fraction = rest << 2;
                var one = den << 2;
                var high = ulp << 1;
                var lowMargin = lowerHalved ? ulp : high;
                var whole = (ulong)d;
                for (var n = shortest; n <= 17; n++)
                {
                    var unit = Pow10[17 - n];
                    var q = whole / unit;
                    var below = (whole - q * unit) * one + fraction;
                    var above = unit * one - below;
                    var pick = Pick(below < lowMargin || (ends && below == lowMargin), above < high || (ends && above == high), below.CompareTo(above), q);
                    if (pick < 0) continue;
                    Finish((ulong)pick, n, 17 - k, out digits, out count, out scale);
                    return;
                }
                break;
            }
            throw new InvalidOperationException("No 17-digit neighbour of " + f + "·2^" + e + " reads back to it."); // cannot happen: see the remarks
        }

        // The neighbour q or q + 1 to write, or -1 when neither is inside the interval.
        static long Pick(bool belowInside, bool aboveInside, int belowVersusAbove, ulong q)
        {
            if (!belowInside && !aboveInside) return -1;
            bool up = aboveInside && (!belowInside || belowVersusAbove > 0 || (belowVersusAbove == 0 && (q & 1) == 1));
            return (long)(up ? q + 1 : q);
        }

        // n digits 0.candidate × 10^scale17 → the digit string without trailing zeros.
        static void Finish(ulong candidate, int n, int scale17, out ulong digits, out int count, out int scale)
        {
            scale = scale17;
            if (candidate == Pow10[n])
            {
                candidate = Pow10[n - 1]; // 99…9 rounded up to 100…0: one place more
                scale++;
            }
            count = n;
            while (candidate % 10 == 0)
            {
                candidate /= 10;
                count--;
            }
            digits = candidate;
        }

        static int LeadingZeros(ulong x)
        {
            var n = 0;
            if (x >> 32 == 0) { n += 32; x <<= 32; }
            if (x >> 48 == 0) { n += 16; x <<= 16; }
            if (x >> 56 == 0) { n += 8; x <<= 8; }
            if (x >> 60 == 0) { n += 4; x <<= 4; }
            if (x >> 62 == 0) { n += 2; x <<= 2; }
            if (x >> 63 == 0) n++;
            return n;
        }
    }
}
