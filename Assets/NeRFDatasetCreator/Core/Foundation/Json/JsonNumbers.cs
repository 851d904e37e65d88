using System;
using System.Globalization;
using System.IO;
using System.Text;
using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Numbers and JSON text exactly as every file of a dataset writes them: invariant culture, the shortest text
    /// that reads back to the same double, never NaN or infinity, space indentation, "\n" line ends.
    /// </summary>
    public static class JsonNumbers
    {
        /// <summary>
        /// The shortest text that reads back to <paramref name="value"/> — .NET Core 3.0+'s "R" digits
        /// (<see cref="ShortestDoubleText"/>, the same on Mono) — with ".0" on whole numbers and a lowercase exponent as
        /// Python's json module (which wrote nerf_synthetic) writes them.
        /// </summary>
        /// <exception cref="ArgumentException">NaN or infinity, which JSON cannot hold.</exception>
        public static string Format(double value) =>
            ShortestDoubleText.Json(value); // 0.0 also for −0, whose sign means nothing in a pose and only puzzles readers

        public static void Write(JsonWriter writer, double value) => writer.WriteRawValue(Format(value));

        /// <summary>
        /// <c>"name": value</c> through <see cref="Format"/>: the one way a dataset file's number key is written (throws
        /// on NaN or infinity, which a dataset file cannot hold).
        /// </summary>
        public static void Number(JsonWriter writer, string name, double value)
        {
            writer.WritePropertyName(name);
            Write(writer, value);
        }

        /// <summary>
        /// A settings file's <c>"name": value</c>: as <see cref="Number"/>, but NaN and infinity are written as strings
        /// ("NaN") — a config may hold one while being edited, the file stays JSON, and validation (not the writer)
        /// reports it; the settings reader reads such a string back as the number.
        /// </summary>
        public static void SettingNumber(JsonWriter writer, string name, double value)
        {
            writer.WritePropertyName(name);
            SettingValue(writer, value);
        }

        /// <summary>The value of <see cref="SettingNumber"/> alone (in a list such as <c>[r, g, b]</c>).</summary>
        public static void SettingValue(JsonWriter writer, double value)
        {
            if (double.IsNaN(value) || double.IsInfinity(value)) writer.WriteValue(value.ToString(CultureInfo.InvariantCulture));
            else Write(writer, value);
        }

        /// <summary>A JSON tree (e.g. <see cref="SceneNormalisation.ToJson"/>) with every double through <see cref="Format"/>.</summary>
        public static void WriteToken(JsonWriter writer, Newtonsoft.Json.Linq.JToken token)
        {
            switch (token.Type)
            {
                case Newtonsoft.Json.Linq.JTokenType.Object:
                    writer.WriteStartObject();
                    foreach (var property in ((Newtonsoft.Json.Linq.JObject)token).Properties())
                    {
                        writer.WritePropertyName(property.Name);
                        WriteToken(writer, property.Value);
                    }
                    writer.WriteEndObject();
                    break;
                case Newtonsoft.Json.Linq.JTokenType.Array:
                    writer.WriteStartArray();
                    foreach (var item in (Newtonsoft.Json.Linq.JArray)token) WriteToken(writer, item);
                    writer.WriteEndArray();
                    break;
                case Newtonsoft.Json.Linq.JTokenType.Float:
                    Write(writer, (double)token);
                    break;
                default:
                    token.WriteTo(writer);
                    break;
            }
        }

        /// <summary>A writer over <paramref name="text"/> with the dataset's formatting.</summary>
        public static JsonTextWriter CreateWriter(TextWriter text, int indentation = 2)
        {
            text.NewLine = "\n";
            return new JsonTextWriter(text)
            {
                Formatting = Formatting.Indented,
                Indentation = indentation,
                IndentChar = ' ',
                Culture = CultureInfo.InvariantCulture,
                FloatFormatHandling = FloatFormatHandling.String,
            };
        }

        public static StringWriter CreateText() => new StringWriter(new StringBuilder(), CultureInfo.InvariantCulture) { NewLine = "\n" };

        /// <summary>
        /// A UTF-8 (no BOM) file writer with the same invariant culture and "\n" line ends as <see cref="CreateText"/>,
        /// for files too large to build as one string first (a transforms file of 300 000 views is 250 MB of text).
        /// </summary>
        public static StreamWriter CreateFile(string path) => new InvariantStreamWriter(path);

        sealed class InvariantStreamWriter : StreamWriter
        {
            public InvariantStreamWriter(string path) : base(path, false, new UTF8Encoding(false), 1 << 16) => NewLine = "\n";

            public override IFormatProvider FormatProvider => CultureInfo.InvariantCulture;
        }
    }
}
