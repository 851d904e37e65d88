using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    static class VerbatimJson
    {
        /// <summary>
        /// Parses JSON keeping strings as written: Newtonsoft's default turns ISO dates into DateTime and writes
        /// them back in another format, which would silently change a frame's or the config's text.
        /// </summary>
        public static JToken Parse(string json)
        {
            using (var reader = new JsonTextReader(new StringReader(json)) { DateParseHandling = DateParseHandling.None })
            {
                var token = JToken.ReadFrom(reader);
                while (reader.Read())
                    if (reader.TokenType != JsonToken.Comment)
                        throw new JsonReaderException("Additional text after the JSON value at line " + reader.LineNumber + ".");
                return token;
            }
        }
    }
}
