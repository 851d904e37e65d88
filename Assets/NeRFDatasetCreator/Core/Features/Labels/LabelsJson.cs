using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>labels.json</c> (Documentation~/output-format.md, "labels.json"): every instance id with its object's name,
    /// hierarchy path, class and display colour, and every class id with its name and colour. Written by the capture
    /// beside the transforms files; read by merge (shards must agree), check and the exports.
    /// </summary>
    public static class LabelsJson
    {
        public const string Format = "nerf-dataset-labels";
        public const int Version = 1;

        public static string Write(LabelTable table)
        {
            if (table == null) throw new ArgumentNullException(nameof(table));
            var root = new JObject
            {
                ["format"] = Format,
                ["version"] = Version,
                ["background"] = 0,
                ["instance_rule"] = InstanceRules.Name(table.Settings.Instances),
                ["class_from"] = ClassSources.Name(table.Settings.ClassFrom),
                ["classes"] = new JArray(table.Classes.Select(c => new JObject
                {
                    ["id"] = c.Id,
                    ["name"] = c.Name,
                    ["colour"] = c.Colour,
                })),
                ["instances"] = new JArray(table.Instances.Select(i => new JObject
                {
                    ["id"] = i.Id,
                    ["name"] = i.Name,
                    ["path"] = i.Path,
                    ["sibling_path"] = new JArray(i.SiblingPath.Select(s => (object)s).ToArray()),
                    ["class_id"] = i.ClassId,
                    ["class"] = i.ClassName,
                    ["colour"] = i.Colour,
                })),
            };
            return root.ToString(Formatting.Indented) + "\n";
        }

        /// <summary>The most ids a list may hold: the largest value of the 16-bit maps (0 is the background).</summary>
        public const int MaxIds = ushort.MaxValue;

        /// <summary>Reads <c>labels.json</c> at <paramref name="path"/>; throws <see cref="InvalidParameterException"/> naming the file, the field and the fix.</summary>
        public static LabelTable ReadFile(string path)
        {
            var text = MetadataText.Read(path, "does not exist, but the dataset's frames name instance/semantic maps.",
                "Recapture with labels on, or restore labels.json from the capture's folder.", "Check the file's permissions.");
            return Parse(text, path);
        }

        /// <summary>Parses the text of a labels.json; <paramref name="source"/> (its path) prefixes the fields in problems.</summary>
        public static LabelTable Parse(string json, string source)
        {
            JObject root;
            try
            {
                root = VerbatimJson.Parse(json) as JObject;
                if (root == null) throw new JsonReaderException("The top level is not a JSON object.");
            }
            catch (JsonException e)
            {
                throw Problem(source, "", "(unreadable)", "is not valid JSON: " + e.Message, "Restore labels.json from the capture, or recapture.");
            }
            var problems = new List<ValidationProblem>();
            if (!(root["format"] is JValue format && format.Type == JTokenType.String && (string)format == Format))
                problems.Add(new ValidationProblem(source + ": format", root["format"]?.ToString(Formatting.None) ?? "(missing)", "is not \"" + Format + "\".",
                    "Use the labels.json the NeRF Dataset Creator capture wrote."));
            if (!JsonValues.TryLong(root["version"], out var version) || version != Version)
                problems.Add(new ValidationProblem(source + ": version", root["version"]?.ToString(Formatting.None) ?? "(missing)", "is not " + Version.ToString(CultureInfo.InvariantCulture) + ".",
                    "Read it with the version of the tool that captured the dataset."));
            var settings = new LabelSettings { Enabled = true };
            if (root["instance_rule"] is JValue ir && ir.Type == JTokenType.String && InstanceRules.TryParse((string)ir, out var rule)) settings.Instances = rule;
            if (root["class_from"] is JValue cf && cf.Type == JTokenType.String && ClassSources.TryParse((string)cf, out var from)) settings.ClassFrom = from;

            // Ids run 1, 2, 3… and the instance and semantic maps are 16-bit: a longer list cannot be what a capture wrote
            // (it ended in an IndexOutOfRange in the Gaussian Grouping export), and is refused before its entries are read.
            foreach (var key in new[] { "classes", "instances" })
                if (root[key] is JArray list && list.Count > MaxIds)
                    throw Problem(source, key, list.Count + " entries", "has more than the " + MaxIds + " ids a 16-bit instance or semantic map can hold.", "Restore labels.json from the capture.");
            var classes = new List<ClassLabel>();
            var classArray = root["classes"] as JArray;
            if (classArray == null) problems.Add(new ValidationProblem(source + ": classes", root["classes"]?.ToString(Formatting.None) ?? "(missing)", "is not a list.", "Restore labels.json from the capture."));
            else
                for (var i = 0; i < classArray.Count; i++)
                {
                    var at = source + ": classes[" + i.ToString(CultureInfo.InvariantCulture) + "]";
                    var c = classArray[i] as JObject;
                    var id = Id(c, "id", at, i + 1, problems);
                    var name = Text(c, "name", at, problems);
                    if (id.HasValue && name != null) classes.Add(new ClassLabel(id.Value, name));
                }

            var instances = new List<InstanceLabel>();
            var instanceArray = root["instances"] as JArray;
            if (instanceArray == null) problems.Add(new ValidationProblem(source + ": instances", root["instances"]?.ToString(Formatting.None) ?? "(missing)", "is not a list.", "Restore labels.json from the capture."));
            else
                for (var i = 0; i < instanceArray.Count; i++)
                {
                    var at = source + ": instances[" + i.ToString(CultureInfo.InvariantCulture) + "]";
                    var o = instanceArray[i] as JObject;
                    var id = Id(o, "id", at, i + 1, problems);
                    var name = Text(o, "name", at, problems);
                    var path = Text(o, "path", at, problems);
                    var siblings = Siblings(o, at, problems);
                    int classId = 0;
                    if (o != null)
                    {
                        if (JsonValues.TryLong(o["class_id"], out var cid) && cid >= 0 && cid <= classes.Count) classId = (int)cid;
                        else
                            problems.Add(new ValidationProblem(at + ".class_id", o["class_id"]?.ToString(Formatting.None) ?? "(missing)",
                                "is not 0 or the id of a class in \"classes\".", "Restore labels.json from the capture."));
                    }
                    if (id.HasValue && name != null && path != null && siblings != null)
                        instances.Add(new InstanceLabel(id.Value, name, path, siblings, classId, classId == 0 ? "" : classes.FirstOrDefault(c => c.Id == classId)?.Name));
                }
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            return LabelTable.FromRows(settings, classes, instances);
        }

        /// <summary>
        /// Why two captures' tables differ (null when they agree): every id names the same object (key), name and class in
        /// both. Merge refuses shards whose tables differ, since an id must mean one object in the whole dataset.
        /// </summary>
        public static string Difference(LabelTable a, LabelTable b)
        {
            if (a.Settings.Instances != b.Settings.Instances || a.Settings.ClassFrom != b.Settings.ClassFrom)
                return "the label rules differ (instances \"" + InstanceRules.Name(a.Settings.Instances) + "\", classes from \"" + ClassSources.Name(a.Settings.ClassFrom) +
                       "\" against \"" + InstanceRules.Name(b.Settings.Instances) + "\", \"" + ClassSources.Name(b.Settings.ClassFrom) + "\")";
            for (var i = 0; i < Math.Max(a.Classes.Count, b.Classes.Count); i++)
            {
                var x = i < a.Classes.Count ? a.Classes[i] : null;
                var y = i < b.Classes.Count ? b.Classes[i] : null;
                if (x == null || y == null || x.Name != y.Name)
                    return "class id " + (i + 1).ToString(CultureInfo.InvariantCulture) + " is " + Describe(x?.Name) + " in one and " + Describe(y?.Name) + " in the other";
            }
            for (var i = 0; i < Math.Max(a.Instances.Count, b.Instances.Count); i++)
            {
                var x = i < a.Instances.Count ? a.Instances[i] : null;
                var y = i < b.Instances.Count ? b.Instances[i] : null;
                if (x == null || y == null || x.Key != y.Key || x.ClassId != y.ClassId)
                    return "instance id " + (i + 1).ToString(CultureInfo.InvariantCulture) + " is " + Describe(x?.Path, x?.ClassName) + " in one and " + Describe(y?.Path, y?.ClassName) + " in the other";
            }
            return null;
        }

        static string Describe(string name) => name == null ? "missing" : "\"" + name + "\"";

        static string Describe(string path, string className) =>
            path == null ? "missing" : "\"" + path + "\"" + (string.IsNullOrEmpty(className) ? "" : " (" + className + ")");

        static int? Id(JObject o, string key, string at, int expected, List<ValidationProblem> problems)
        {
            if (o == null)
            {
                problems.Add(new ValidationProblem(at, "(not an object)", "is not an object { \"id\": … }.", "Restore labels.json from the capture."));
                return null;
            }
            if (!JsonValues.TryLong(o[key], out var id) || id != expected)
            {
                problems.Add(new ValidationProblem(at + "." + key, o[key]?.ToString(Formatting.None) ?? "(missing)",
                    "is not " + expected.ToString(CultureInfo.InvariantCulture) + ": ids run 1, 2, 3… in the order of the list.", "Restore labels.json from the capture."));
                return null;
            }
            return (int)id;
        }

        static string Text(JObject o, string key, string at, List<ValidationProblem> problems)
        {
            if (o == null) return null;
            if (o[key] is JValue v && v.Type == JTokenType.String) return (string)v;
            problems.Add(new ValidationProblem(at + "." + key, o[key]?.ToString(Formatting.None) ?? "(missing)", "is not a string.", "Restore labels.json from the capture."));
            return null;
        }

        static int[] Siblings(JObject o, string at, List<ValidationProblem> problems)
        {
            if (o == null) return null;
            if (o["sibling_path"] is JArray array)
            {
                var result = new int[array.Count];
                var ok = array.Count > 0;
                for (var i = 0; i < array.Count && ok; i++)
                {
                    ok = JsonValues.TryLong(array[i], out var s) && s >= 0 && s <= int.MaxValue;
                    if (ok) result[i] = (int)s;
                }
                if (ok) return result;
            }
            problems.Add(new ValidationProblem(at + ".sibling_path", o["sibling_path"]?.ToString(Formatting.None) ?? "(missing)",
                "is not a non-empty list of sibling indices.", "Restore labels.json from the capture."));
            return null;
        }

        static InvalidParameterException Problem(string source, string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(source + (field.Length > 0 ? ": " + field : ""), value, reason, fix) });
    }
}
