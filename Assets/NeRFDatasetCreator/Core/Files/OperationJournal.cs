using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The small record every multi-step operation keeps in its working folder (<see cref="FileName"/>), so that
    /// the next run on the same output can finish it or roll it back (<see cref="Recovery"/>):
    /// <code>
    /// { "format": "nerf-dataset-creator/operation", "version": 1, "operation": "write", "output": "/abs/lego",
    ///   "state": "writing", "aside": null, "shards": [], "moves": [], "files": [],
    ///   "owner": { "host": "studio-7", "pid": 4242, "started": "2026-11-27T11:54:01.0000000Z" } }
    /// </code>
    /// <see cref="State"/> is <see cref="Writing"/> while files are being produced (the output is untouched: roll
    /// back) and <see cref="Committing"/> once everything is complete in the working folder (finish). Rewritten through
    /// a temporary file so that a kill leaves either the old or the new record readable.
    /// </summary>
    public sealed class OperationJournal
    {
        public const string FileName = ".nerf-operation.json";
        const string TempName = FileName + ".tmp";
        public const string FormatName = "nerf-dataset-creator/operation";

        public const string Writing = "writing";
        public const string Committing = "committing";

        /// <summary>"write" (plan and capture), "merge" or "convert".</summary>
        public string Operation;

        /// <summary>The absolute output folder the operation produces.</summary>
        public string Output;

        public string State = Writing;

        /// <summary>write: where the replaced dataset is moved while the new one takes its name.</summary>
        public string Aside;

        /// <summary>merge --files move: each shard file (absolute) and its path relative to the working folder.</summary>
        public List<KeyValuePair<string, string>> Moves = new List<KeyValuePair<string, string>>();

        /// <summary>
        /// merge: the shard folders (absolute) the merge read. Every <see cref="Moves"/> source must lie inside one of
        /// them, or recovery refuses the journal (<see cref="JournalPaths"/>): a journal is a file anyone can edit.
        /// </summary>
        public List<string> Shards = new List<string>();

        /// <summary>convert: the files, relative to the working folder and to the output alike, to move into place.</summary>
        public List<string> Files = new List<string>();

        /// <summary>convert: the output folder did not exist and was created by the operation (removed again on roll-back when empty).</summary>
        public bool CreatedOutput;

        /// <summary>
        /// The run writing the operation (this process, for a journal made here): recovery and clean leave the folder of
        /// a run that may still be writing alone (<see cref="OperationOwner.WhyMayBeRunning"/>). Null in journals from
        /// before owners were recorded.
        /// </summary>
        public OperationOwner Owner = OperationOwner.Current;

        public static string PathIn(string folder) => Path.Combine(folder, FileName);

        public void Save(string folder)
        {
            var json = new JObject
            {
                ["format"] = FormatName,
                ["version"] = 1,
                ["operation"] = Operation,
                ["output"] = Output,
                ["state"] = State,
                ["aside"] = Aside,
                ["createdOutput"] = CreatedOutput,
                ["shards"] = new JArray(Shards.Cast<object>().ToArray()),
                ["moves"] = new JArray(Moves.Select(m => new JObject { ["from"] = m.Key, ["to"] = m.Value })),
                ["files"] = new JArray(Files.Cast<object>().ToArray()),
            };
            if (Owner != null)
                json["owner"] = new JObject
                {
                    ["host"] = Owner.Host,
                    ["pid"] = Owner.ProcessId,
                    ["started"] = Owner.ProcessStart?.ToString("o", System.Globalization.CultureInfo.InvariantCulture),
                };
            var temp = Path.Combine(folder, TempName);
            var path = PathIn(folder);
            FileOps.WriteText(temp, json.ToString(Formatting.Indented) + "\n");
            if (File.Exists(path)) FileOps.DeleteFile(path);
            FileOps.MoveFile(temp, path);
        }

        /// <summary>Removes the record (the operation is complete).</summary>
        public static void Delete(string folder)
        {
            foreach (var name in new[] { TempName, FileName })
            {
                var path = Path.Combine(folder, name);
                if (File.Exists(path)) FileOps.DeleteFile(path);
            }
        }

        /// <summary>The record in <paramref name="folder"/>, or null when it has none or it is unreadable (never throws for a bad file).</summary>
        public static OperationJournal Load(string folder)
        {
            foreach (var name in new[] { FileName, TempName })
            {
                var path = Path.Combine(folder, name);
                if (!File.Exists(path)) continue;
                try
                {
                    if (JToken.Parse(FileOps.ReadText(path)) is JObject o && (string)o["format"] == FormatName) return FromJson(o);
                }
                catch (JsonException) { }
                catch (System.ArgumentException) { }
                catch (System.FormatException) { }
                catch (System.InvalidCastException) { }
                catch (IOException) { }
                catch (System.UnauthorizedAccessException) { }
            }
            return null;
        }

        static OperationJournal FromJson(JObject o)
        {
            var journal = new OperationJournal
            {
                Operation = (string)o["operation"],
                Output = (string)o["output"],
                State = (string)o["state"] ?? Writing,
                Aside = (string)o["aside"],
                CreatedOutput = o["createdOutput"]?.Type == JTokenType.Boolean && (bool)o["createdOutput"],
                Owner = OwnerOf(o["owner"] as JObject),
            };
            if (o["moves"] is JArray moves)
                foreach (var m in moves.OfType<JObject>())
                    if ((string)m["from"] != null && (string)m["to"] != null)
                        journal.Moves.Add(new KeyValuePair<string, string>((string)m["from"], (string)m["to"]));
            if (o["shards"] is JArray shards)
                journal.Shards.AddRange(shards.Where(f => f.Type == JTokenType.String).Select(f => (string)f));
            if (o["files"] is JArray files)
                journal.Files.AddRange(files.Where(f => f.Type == JTokenType.String).Select(f => (string)f));
            return journal;
        }

        static OperationOwner OwnerOf(JObject owner)
        {
            // An owner that cannot be read is treated as none: the journal then behaves as one from before owners existed.
            if (owner == null || owner["pid"]?.Type != JTokenType.Integer || !(owner["pid"] is JValue pid) || !(pid.Value is long id) || id < 0 || id > int.MaxValue) return null;
            DateTime? started = null;
            if (owner["started"]?.Type == JTokenType.String &&
                DateTime.TryParse((string)owner["started"], System.Globalization.CultureInfo.InvariantCulture,
                    System.Globalization.DateTimeStyles.AdjustToUniversal | System.Globalization.DateTimeStyles.AssumeUniversal, out var parsed))
                started = parsed;
            else if (owner["started"]?.Type == JTokenType.Date) started = ((DateTime)owner["started"]).ToUniversalTime();
            return new OperationOwner(owner["host"]?.Type == JTokenType.String ? (string)owner["host"] : "", (int)id, started);
        }
    }
}
