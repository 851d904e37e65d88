using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ShortestDoubleTextTests
    {
        // .NET Core 3.0+ formats "R" as the shortest round-trip text; Mono (Unity) and .NET Framework do not.
        static bool RuntimeRIsShortest => Type.GetType("Mono.Runtime") == null && Environment.Version.Major >= 5;

        [TestCase(1.0, "1.0")]
        [TestCase(0.1, "0.1")]
        [TestCase(0.1 + 0.2, "0.30000000000000004")]
        [TestCase(-0.0, "0.0")]
        [TestCase(1e15, "1000000000000000.0")]
        [TestCase(1e16, "10000000000000000.0")]
        [TestCase(1e17, "1e+17")]          // .NET's "R" switches to an exponent above 17 places…
        [TestCase(123456789012345678.0, "1.2345678901234568e+17")]
        [TestCase(1234567890123456.7, "1234567890123456.8")]
        [TestCase(0.0001, "0.0001")]
        [TestCase(1e-5, "1e-05")]          // …and below 1e-4, with at least two exponent digits
        [TestCase(1.2345e-5, "1.2345e-05")]
        [TestCase(-2.5e20, "-2.5e+20")]
        [TestCase(1.1102230246251565e-16, "1.1102230246251565e-16")]
        [TestCase(double.Epsilon, "5e-324")]
        [TestCase(double.MaxValue, "1.7976931348623157e+308")]
        [TestCase(2.2250738585072014e-308, "2.2250738585072014e-308")] // the smallest normal double
        [TestCase(9007199254740993.0, "9007199254740992.0")]          // 2^53 + 1 is not a double: 2^53
        public void WritesDotNetsRoundTripText(double value, string expected)
        {
            Assert.That(ShortestDoubleText.Json(value), Is.EqualTo(expected));
        }

        [Test]
        public void PowersOfTwoWhoseDotNetTextDoesNotReadBackGetTheDigitsThatDo()
        {
            // .NET 10's own "R" writes 2^-25 as 2.980232238769531E-08, which reads back as the double below it (the
            // interval below a power of two is half as wide); the same for 2^-958. Here they take 17 digits.
            var a = Math.Pow(2, -25);
            var b = Math.Pow(2, -958);
            Assert.That(ShortestDoubleText.Json(a), Is.EqualTo("2.9802322387695312e-08"));
            Assert.That(ShortestDoubleText.Json(b), Is.EqualTo("4.1045368012983762e-289"));
            Assert.That(ReadsBackExactly("2.9802322387695312e-08", a), Is.True);
            Assert.That(ReadsBackExactly("2.980232238769531e-08", a), Is.False, "the shorter text is really another double's");
        }

        [Test]
        public void IsTheShortestClosestTextByExactArithmetic()
        {
            // An oracle independent of every runtime's formatting and parsing (so it also holds Mono to account): the
            // text's exact decimal value lies in the double's rounding interval, no decimal with one digit fewer does,
            // and of the two neighbours at its length it is the closer one that does.
            foreach (var signed in Sample(new SeededRandom(13), 20000))
            {
                if (signed == 0) continue;
                var value = Math.Abs(signed);
                var text = ShortestDoubleText.Json(value);
                Assert.That(ShortestDoubleText.Json(signed), Is.EqualTo(signed < 0 ? "-" + text : text));
                Assert.That(ReadsBackExactly(text, value), Is.True, text);
                ParseExact(text, out var digits, out var exponent);
                var count = digits.ToString(CultureInfo.InvariantCulture).Length;
                var scale = exponent + count; // value ≈ 0.digits × 10^scale (digits rounded up to a power of 10 have count 1)
                // A shorter decimal that reads back would also be one with count − 1 digits, next to the value.
                if (count > 1)
                    Assert.That(NeighbourReadsBack(value, count - 1, scale, out _, out _), Is.False, text + " has a shorter form");
                NeighbourReadsBack(value, count, scale, out var below, out var above);
                if (below != null && above != null)
                {
                    var chosen = new BigRational(digits, exponent);
                    var exact = BigRational.Of(value);
                    var other = chosen.Equals(below) ? above : below;
                    Assert.That(chosen.Distance(exact).CompareTo(other.Distance(exact)), Is.LessThanOrEqualTo(0), text + " is not the closer neighbour");
                }
            }
        }

        [Test]
        public void MatchesDotNetsRoundTripTextOnMillionsOfDoubles()
        {
            if (!RuntimeRIsShortest) Assert.Ignore("this runtime's \"R\" is not the shortest round-trip text (Mono, .NET Framework): the exact test above covers it");
            var random = new SeededRandom(2024);
            var differ = 0;
            foreach (var value in Sample(random, 1500000))
            {
                var ours = ShortestDoubleText.Json(value);
                var theirs = value == 0 ? "0.0" : value.ToString("R", CultureInfo.InvariantCulture).Replace("E", "e");
                if (theirs.IndexOf('.') < 0 && theirs.IndexOf('e') < 0) theirs += ".0";
                if (ours == theirs) continue;
                // Only where .NET's own text does not read back (powers of two, see above) may ours differ.
                Assert.That(double.Parse(theirs, CultureInfo.InvariantCulture), Is.Not.EqualTo(value), "ours " + ours + ", .NET " + theirs);
                Assert.That(double.Parse(ours, CultureInfo.InvariantCulture), Is.EqualTo(value), ours);
                differ++;
            }
            Assert.That(differ, Is.LessThan(10));
        }

        [Test]
        public void NeedsNoCulture()
        {
            var saved = CultureInfo.CurrentCulture;
            try
            {
                CultureInfo.CurrentCulture = new CultureInfo("de-DE");
                Assert.That(ShortestDoubleText.Json(-1234.5678), Is.EqualTo("-1234.5678"));
                Assert.That(JsonNumbers.Format(0.25), Is.EqualTo("0.25"));
            }
            finally
            {
                CultureInfo.CurrentCulture = saved;
            }
        }

        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void RefusesWhatJsonCannotHold(double value)
        {
            Assert.Throws<ArgumentException>(() => ShortestDoubleText.WriteJson(value, new char[ShortestDoubleText.MaxLength], 0));
        }

        [Test]
        public void WritesIntoTheBufferAtTheGivenPlace()
        {
            var buffer = new char[40];
            buffer[0] = '[';
            var end = ShortestDoubleText.WriteJson(-0.5, buffer, 1);
            buffer[end++] = ']';
            Assert.That(new string(buffer, 0, end), Is.EqualTo("[-0.5]"));
        }

        /// <summary>Random bit patterns, pose-like values, every decade and binade with their neighbours, subnormals, whole numbers.</summary>
        static IEnumerable<double> Sample(SeededRandom random, int randomCount)
        {
            for (var i = 0; i < randomCount / 3; i++)
            {
                var bits = BitConverter.Int64BitsToDouble((long)random.NextUInt64());
                if (!double.IsNaN(bits) && !double.IsInfinity(bits)) yield return bits;
                yield return (random.NextDouble() - 0.5) * 20;
                yield return random.NextDouble() * Math.Pow(10, (int)(random.NextDouble() * 60) - 30);
            }
            for (var e = -1074; e <= 1023; e++)
                foreach (var d in Around(Math.Pow(2, e), 2)) yield return d;
            for (var e = -323; e <= 308; e++)
                foreach (var d in Around(double.Parse("1e" + e, CultureInfo.InvariantCulture), 3)) yield return d;
            for (long b = 1; b < 2000; b++)
            {
                yield return BitConverter.Int64BitsToDouble(b);                          // subnormals
                yield return BitConverter.Int64BitsToDouble(0x7FEFFFFFFFFFFFFFL - b);    // the largest doubles
                yield return b;
                yield return b * 1e15;
                yield return -b * 0.001;
            }
            yield return -0.0;
            yield return double.Epsilon;
            yield return double.MaxValue;
        }

        static IEnumerable<double> Around(double value, int steps)
        {
            var bits = BitConverter.DoubleToInt64Bits(value);
            for (var d = -steps; d <= steps; d++)
            {
                var near = BitConverter.Int64BitsToDouble(bits + d);
                if (near > 0 && !double.IsInfinity(near)) yield return near;
            }
        }

        // Exact reading of "[-]d.ddde±x" / "[-]ddd.ddd" as digits × 10^exponent.
        static void ParseExact(string text, out BigInteger digits, out int exponent)
        {
            var e = text.IndexOf('e');
            exponent = e >= 0 ? int.Parse(text.Substring(e + 1), CultureInfo.InvariantCulture) : 0;
            var mantissa = e >= 0 ? text.Substring(0, e) : text;
            var point = mantissa.IndexOf('.');
            if (point >= 0)
            {
                exponent -= mantissa.Length - point - 1;
                mantissa = mantissa.Remove(point, 1);
            }
            digits = BigInteger.Parse(mantissa, CultureInfo.InvariantCulture);
            while (!digits.IsZero && digits % 10 == 0)
            {
                digits /= 10;
                exponent++;
            }
        }

        static bool ReadsBackExactly(string text, double value)
        {
            ParseExact(text, out var digits, out var exponent);
            return Inside(new BigRational(BigInteger.Abs(digits), exponent), Math.Abs(value));
        }

        // Whether a decimal reads back as value under round-to-nearest-even: inside the interval halfway to the
        // neighbouring doubles, or on its end when value's last bit is even.
        static bool Inside(BigRational candidate, double value)
        {
            var bits = BitConverter.DoubleToInt64Bits(value);
            var lower = BigRational.Of(BitConverter.Int64BitsToDouble(bits - 1));
            var upper = BitConverter.Int64BitsToDouble(bits + 1);
            var exact = BigRational.Of(value);
            var high = double.IsInfinity(upper) ? exact.Plus(exact.Minus(lower)) : BigRational.Of(upper);
            var low = value == double.Epsilon ? BigRational.Zero : lower;
            var even = (bits & 1) == 0;
            var aboveLow = candidate.Twice().CompareTo(exact.Plus(low));
            var belowHigh = candidate.Twice().CompareTo(exact.Plus(high));
            return (aboveLow > 0 || (even && aboveLow == 0)) && (belowHigh < 0 || (even && belowHigh == 0));
        }

        // The n-digit decimals just below and above value (value ≈ 0.d × 10^scale), each null when it does not read back.
        static bool NeighbourReadsBack(double value, int n, int scale, out BigRational below, out BigRational above)
        {
            var exact = BigRational.Of(value);
            var step = n - scale; // n-digit decimals at this scale are multiples of 10^-step
            var floor = exact.FloorTimesPowerOf10(step);
            var lo = new BigRational(floor, -step);
            var hi = new BigRational(floor + 1, -step);
            below = Inside(lo, value) ? lo : null;
            above = Inside(hi, value) ? hi : null;
            return below != null || above != null;
        }

        /// <summary>A non-negative exact rational p / q.</summary>
        sealed class BigRational
        {
            public static readonly BigRational Zero = new BigRational(BigInteger.Zero, BigInteger.One);
            readonly BigInteger _p, _q;

            BigRational(BigInteger p, BigInteger q)
            {
                _p = p;
                _q = q;
            }

            public BigRational(BigInteger digits, int exponent)
                : this(exponent >= 0 ? digits * BigInteger.Pow(10, exponent) : digits, exponent >= 0 ? BigInteger.One : BigInteger.Pow(10, -exponent))
            {
            }

            public static BigRational Of(double value)
            {
                var bits = BitConverter.DoubleToInt64Bits(value);
                var biased = (int)(bits >> 52) & 0x7FF;
                var f = new BigInteger(bits & 0xFFFFFFFFFFFFFL);
                var e = biased == 0 ? -1074 : biased - 1075;
                if (biased != 0) f += BigInteger.One << 52;
                return e >= 0 ? new BigRational(f << e, BigInteger.One) : new BigRational(f, BigInteger.One << -e);
            }

            public BigRational Plus(BigRational o) => new BigRational(_p * o._q + o._p * _q, _q * o._q);
            public BigRational Minus(BigRational o) => new BigRational(_p * o._q - o._p * _q, _q * o._q);
            public BigRational Twice() => new BigRational(_p * 2, _q);
            public BigRational Distance(BigRational o) { var d = Minus(o); return d._p.Sign < 0 ? new BigRational(-d._p, d._q) : d; }
            public int CompareTo(BigRational o) => (_p * o._q).CompareTo(o._p * _q);
            public bool Equals(BigRational o) => o != null && CompareTo(o) == 0;

            public BigInteger FloorTimesPowerOf10(int power) =>
                power >= 0 ? _p * BigInteger.Pow(10, power) / _q : _p / (_q * BigInteger.Pow(10, -power));
        }
    }
}
