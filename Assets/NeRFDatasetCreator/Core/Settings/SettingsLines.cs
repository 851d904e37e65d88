using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a setting is in its config file, so that a range problem (<see cref="SettingsValidator"/>, which sees only
    /// the settings) is placed like a format error: <c>lego.json(14,18): splits.train.count = 0: …</c> (issue 33:
    /// "range errors have no line"). The problem's field is the setting's path in the file; a field the file does not
    /// hold (a default left out) is placed at its nearest enclosing section that is there, or not at all.
    /// </summary>
    public static class SettingsLines
    {
        /// <summary>"source(line,column)" of <paramref name="field"/> in <paramref name="root"/> (read with line info), or null.</summary>
        public static string Where(JObject root, string source, string field)
        {
            if (root == null || string.IsNullOrEmpty(field)) return null;
            for (var path = field; path.Length > 0; path = Parent(path))
            {
                JToken token;
                try
                {
                    token = root.SelectToken(path, false);
                }
                catch (JsonException)
                {
                    token = null; // not a path ("--out", a sentence): not placed
                }
                if (token is IJsonLineInfo info && info.HasLineInfo() && token != root)
                {
                    // The value's place, as the format errors give it (DatasetSettingsJson: the token's line info).
                    return (string.IsNullOrEmpty(source) ? "config" : source) + "(" + info.LineNumber + "," + info.LinePosition + ")";
                }
            }
            return null;
        }

        static string Parent(string path)
        {
            var dot = path.LastIndexOf('.');
            var bracket = path.LastIndexOf('[');
            var cut = System.Math.Max(dot, bracket);
            return cut > 0 ? path.Substring(0, cut) : "";
        }
    }
}
