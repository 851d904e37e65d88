using System;
using System.Globalization;
using System.Numerics;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The one reader of numbers in every file the plugin reads (transforms, shard.json, configs, journals).
    /// Newtonsoft holds a whole number beyond 64 bits as a <see cref="BigInteger"/>, which the usual casts
    /// (<c>(long)token</c>, <c>Convert.ToDouble</c>) turn into a crash; here it is a value like any other, read as a
    /// double (finite up to about 1.8e308) or refused as out of range, so callers report it with the field's name.
    /// </summary>
    public static class JsonValues
    {
        /// <summary>A JSON number (any size) as a double; false for anything else.</summary>
        public static bool TryNumber(JToken token, out double value)
        {
            value = 0;
            if (token == null || (token.Type != JTokenType.Integer && token.Type != JTokenType.Float)) return false;
            var raw = ((JValue)token).Value;
            if (raw is BigInteger big) value = (double)big;
            else if (raw is double d) value = d;
            else if (raw is decimal m) value = (double)m;
            else value = Convert.ToDouble(raw, CultureInfo.InvariantCulture);
            return true;
        }

        /// <summary>A whole JSON number within <c>long</c>; false for fractions, anything beyond 64 bits and non-numbers.</summary>
        public static bool TryLong(JToken token, out long value)
        {
            value = 0;
            if (token == null || token.Type != JTokenType.Integer) return false;
            var raw = ((JValue)token).Value;
            if (raw is BigInteger big)
            {
                if (big < long.MinValue || big > long.MaxValue) return false;
                value = (long)big;
                return true;
            }
            value = Convert.ToInt64(raw, CultureInfo.InvariantCulture);
            return true;
        }

        /// <summary>A whole JSON number within <c>int</c>.</summary>
        public static bool TryInt(JToken token, out int value)
        {
            value = 0;
            if (!TryLong(token, out var wide) || wide < int.MinValue || wide > int.MaxValue) return false;
            value = (int)wide;
            return true;
        }
    }
}
