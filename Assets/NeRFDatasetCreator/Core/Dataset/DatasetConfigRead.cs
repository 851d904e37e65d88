using System;
using System.IO;
using System.Runtime.ExceptionServices;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>How reading a folder's <c>dataset_config.json</c> went.</summary>
    public enum DatasetConfigState
    {
        /// <summary>There is none: nerf_synthetic, another tool's dataset.</summary>
        Missing,
        /// <summary>Parsed into <see cref="DatasetConfigFile.Config"/>.</summary>
        Read,
        /// <summary>It exists but cannot be read (permissions, a folder under that name, larger than <see cref="FileOps.MaxTextBytes"/>).</summary>
        Unreadable,
        /// <summary>Its text is not JSON.</summary>
        NotJson,
        /// <summary>Its text is JSON, but not an object.</summary>
        NotAnObject,
    }

    /// <summary>
    /// The outcome of <see cref="DatasetConfig.Read"/>: the config, or why there is none. Callers word the outcome
    /// themselves (validate's problem, convert's warning, a check's skip note), as each did before the one reader.
    /// </summary>
    public sealed class DatasetConfigFile
    {
        internal DatasetConfigFile(string path, DatasetConfigState state, DatasetConfig config, Exception failure)
        {
            Path = path;
            State = state;
            Config = config;
            Failure = failure;
        }

        public string Path { get; }
        public DatasetConfigState State { get; }

        /// <summary>The parsed config; null unless <see cref="State"/> is <see cref="DatasetConfigState.Read"/>.</summary>
        public DatasetConfig Config { get; }

        /// <summary>The exception that stopped the read (an <see cref="IOException"/> or a <see cref="JsonException"/>), or null.</summary>
        public Exception Failure { get; }

        /// <summary>The failure's message (Newtonsoft's words for a parse error, as <c>JObject.Parse</c> gives them), or null.</summary>
        public string Error => Failure?.Message;

        public bool Exists => State != DatasetConfigState.Missing;

        /// <summary>True when the config marks the folder as a plan without images (false when there is none or it cannot be read).</summary>
        public bool IsPlanOnly => Config?.IsPlanOnly == true;

        /// <summary>
        /// Rethrows the read's <see cref="IOException"/> when the file could not be read — for the callers (evaluate,
        /// the Dynamic 3D Gaussians export) that ignore a malformed config but fail on an unreadable one.
        /// </summary>
        public DatasetConfigFile ThrowIfUnreadable()
        {
            if (State == DatasetConfigState.Unreadable) ExceptionDispatchInfo.Capture(Failure).Throw();
            return this;
        }
    }

    public sealed partial class DatasetConfig
    {
        /// <summary>
        /// Reads <paramref name="datasetFolder"/>'s <c>dataset_config.json</c> once, with <see cref="FileOps.ReadText"/>'s
        /// size cap. Never throws for a missing, unreadable or malformed file: the outcome says which.
        /// </summary>
        public static DatasetConfigFile Read(string datasetFolder)
        {
            var path = System.IO.Path.Combine(datasetFolder, FileName);
            if (!File.Exists(path)) return new DatasetConfigFile(path, DatasetConfigState.Missing, null, null);
            string text;
            try
            {
                text = FileOps.ReadText(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return new DatasetConfigFile(path, DatasetConfigState.Unreadable, null, e);
            }
            try
            {
                return new DatasetConfigFile(path, DatasetConfigState.Read, Parse(text), null);
            }
            catch (JsonException e)
            {
                return new DatasetConfigFile(path, IsJson(text) ? DatasetConfigState.NotAnObject : DatasetConfigState.NotJson, null, e);
            }
        }

        /// <summary>
        /// Parses the text of a <c>dataset_config.json</c>: <c>JObject.Parse</c>, with its error messages, except that
        /// strings stay as written (Newtonsoft would turn <c>createdUtc</c> into a DateTime and merge would write it back
        /// in another format). Throws a <see cref="JsonException"/> when the text is not a JSON object.
        /// </summary>
        public static DatasetConfig Parse(string text)
        {
            using (var reader = new JsonTextReader(new StringReader(text ?? "")) { DateParseHandling = DateParseHandling.None })
            {
                var json = JObject.Load(reader);
                while (reader.Read())
                {
                    // Any content after the object other than a comment throws in the reader, as in JObject.Parse.
                }
                return new DatasetConfig(json);
            }
        }

        /// <summary>Whether text that is not a JSON object is JSON at all (an array, a number…): only on the error path.</summary>
        static bool IsJson(string text)
        {
            try
            {
                using (var reader = new JsonTextReader(new StringReader(text ?? "")) { DateParseHandling = DateParseHandling.None })
                {
                    JToken.ReadFrom(reader);
                    while (reader.Read()) { }
                    return true;
                }
            }
            catch (JsonException)
            {
                return false;
            }
        }
    }
}
