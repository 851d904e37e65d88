using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>time</c> record of a parsed dataset_config.json (<see cref="TimeRecord"/> writes it), read leniently: each
    /// value is null when it is missing or of the wrong type, and every reader decides what it needs (validate a valid
    /// mode, start &lt; end and steps ≥ 2; the Dynamic 3D Gaussians export a multi-view mode; evaluate and merge the steps).
    /// </summary>
    public sealed class RecordedTime
    {
        /// <summary><c>mode</c> when it is a string ("monocular", "multi-view", …; <see cref="TimeModes"/>).</summary>
        public string Mode { get; private set; }

        /// <summary><c>startSeconds</c> when it is a number.</summary>
        public double? StartSeconds { get; private set; }

        /// <summary><c>endSeconds</c> when it is a number.</summary>
        public double? EndSeconds { get; private set; }

        /// <summary><c>steps</c> when it is a whole number that fits an int.</summary>
        public int? Steps { get; private set; }

        /// <summary>The record in <paramref name="section"/> (dataset_config.json's <c>time</c>), or null when it is not an object.</summary>
        public static RecordedTime FromJson(JToken section)
        {
            if (!(section is JObject time)) return null;
            return new RecordedTime
            {
                Mode = time["mode"]?.Type == JTokenType.String ? (string)time["mode"] : null,
                StartSeconds = Number(time["startSeconds"]),
                EndSeconds = Number(time["endSeconds"]),
                Steps = WholeNumber(time["steps"]),
            };
        }

        static double? Number(JToken token) => JsonValues.TryNumber(token, out var value) ? (double?)value : null;

        static int? WholeNumber(JToken token)
        {
            if (token?.Type != JTokenType.Integer) return null;
            var value = ((JValue)token).Value;
            if (value is long l) return l >= int.MinValue && l <= int.MaxValue ? (int?)l : null;
            if (value is int i) return i;
            return null; // a BigInteger: no dataset has that many steps
        }
    }
}
