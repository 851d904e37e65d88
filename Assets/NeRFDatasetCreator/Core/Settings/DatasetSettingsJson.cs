using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The config-file form of <see cref="DatasetSettings"/> (see Documentation~/settings.md). Writing is
    /// deterministic; reading accepts missing keys (defaults), warns about unknown keys and other schema versions,
    /// and reports malformed JSON or a wrongly typed value with its line and column.
    /// </summary>
    public static class DatasetSettingsJson
    {
        public static string Write(DatasetSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            using (var text = JsonNumbers.CreateText())
            {
                using (var w = JsonNumbers.CreateWriter(text))
                    WriteObject(w, settings);
                return text.ToString() + "\n"; // the writer's text, formatted by CreateText's invariant culture
            }
        }

        /// <summary>Writes the settings as one JSON object into an open writer (also used inside dataset_config.json).</summary>
        public static void WriteObject(JsonWriter w, DatasetSettings s)
        {
            w.WriteStartObject();
            w.WritePropertyName("schemaVersion"); w.WriteValue(DatasetSettings.CurrentSchemaVersion);
            w.WritePropertyName("name"); w.WriteValue(s.Name ?? "");
            w.WritePropertyName("outputFolder"); w.WriteValue(s.OutputFolder ?? "");
            w.WritePropertyName("scene"); w.WriteValue(s.Scene ?? "");
            w.WritePropertyName("target"); w.WriteValue(s.Target ?? "");
            w.WritePropertyName("camera");
            w.WriteStartObject();
            JsonNumbers.SettingNumber(w, "verticalFovDegrees", s.Camera.VerticalFovDegrees);
            JsonNumbers.SettingNumber(w, "nearClip", s.Camera.NearClip);
            JsonNumbers.SettingNumber(w, "farClip", s.Camera.FarClip);
            w.WritePropertyName("copyFromCamera"); w.WriteValue(s.Camera.CopyFromCamera ?? "");
            w.WriteEndObject();
            if (s.AutoDistance)
            {
                w.WritePropertyName("distance");
                w.WriteValue("auto");
            }
            else JsonNumbers.SettingNumber(w, "distance", s.Distance);
            JsonNumbers.SettingNumber(w, "autoDistanceMargin", s.AutoDistanceMargin);
            w.WritePropertyName("width"); w.WriteValue(s.Width);
            w.WritePropertyName("height"); w.WriteValue(s.Height);
            w.WritePropertyName("supersampling"); w.WriteValue(s.Supersampling);
            w.WritePropertyName("background"); w.WriteValue(s.Background.ToConfigString());
            // Only when chosen, so configs without it keep their keys (eval_protocol.json's background).
            if (s.EvaluationBackground != null)
            {
                w.WritePropertyName(EvalProtocol.SettingsKey);
                w.WriteValue(s.EvaluationBackground);
            }
            w.WritePropertyName("seed"); w.WriteValue(s.Seed);
            w.WritePropertyName("overwrite"); w.WriteValue(OverwriteName(s.Overwrite));
            w.WritePropertyName("loaders");
            w.WriteStartArray();
            foreach (var name in TargetLoaderNames.NamesOf(s.Loaders)) w.WriteValue(name);
            w.WriteEndArray();
            w.WritePropertyName("normalisation"); w.WriteValue(NormalisationModes.IsDefined(s.Normalisation) ? NormalisationModes.Name(s.Normalisation) : ((int)s.Normalisation).ToString(System.Globalization.CultureInfo.InvariantCulture));
            JsonNumbers.SettingNumber(w, "normalisedTargetRadius", s.NormalisedTargetRadius);
            w.WritePropertyName("pointCloudPoints"); w.WriteValue(s.PointCloudPoints);
            // Only when set, so object captures' configs keep their keys (0, the default, picks it from the volume boxes).
            if (s.PointCloudRadius != 0) JsonNumbers.SettingNumber(w, "pointCloudRadius", s.PointCloudRadius);
            // Only when turned off, so existing configs keep their keys.
            if (!s.Preflight)
            {
                w.WritePropertyName("preflight");
                w.WriteValue(false);
            }
            // The optional outputs (Core/Features/<Feature>/), one line each: a section is written only when its
            // feature is on, so configs without it keep their keys (Documentation~/settings.md, "Optional outputs").
            GeometryPackSettingsJson.Write(w, s);
            LensSettingsJson.Write(w, s.Lens);
            TimeSettingsJson.Write(w, s.Time);
            LabelSettingsJson.Write(w, s.Labels);
            ExposureSettingsJson.Write(w, s.Exposure);
            MotionBlurSettingsJson.Write(w, s.MotionBlur);
            SparseViewsSettings.Write(w, s);
            HdrSettingsJson.Write(w, s.Hdr);
            MaterialPassSettingsJson.Write(w, s.Materials);
            RelightingSettingsJson.Write(w, s.Relighting);
            FlowSettingsJson.Write(w, s.Flow);
            w.WritePropertyName("splits");
            w.WriteStartObject();
            foreach (var split in DatasetSplits.All)
            {
                w.WritePropertyName(DatasetSplits.Name(split));
                WriteSplit(w, s.Split(split));
            }
            w.WriteEndObject();
            w.WriteEndObject();
        }

        static void WriteSplit(JsonWriter w, SplitSettings split)
        {
            w.WriteStartObject();
            w.WritePropertyName("count"); w.WriteValue(split.Count);
            w.WritePropertyName("formation");
            w.WriteStartObject();
            var f = split.Formation;
            w.WritePropertyName("kind"); w.WriteValue(FormationKinds.Name(f.Kind));
            foreach (var name in FormationSettings.ParameterNames(f.Kind))
            {
                if (name == "upperHemisphereOnly")
                {
                    w.WritePropertyName(name);
                    w.WriteValue(f.UpperHemisphereOnly);
                }
                else JsonNumbers.SettingNumber(w, name, FormationParameter(f, name));
            }
            w.WriteEndObject();
            w.WritePropertyName("depth"); w.WriteValue(ExtraOutputs.Name(split.Depth));
            w.WritePropertyName("normal"); w.WriteValue(ExtraOutputs.Name(split.Normal));
            w.WritePropertyName("mask"); w.WriteValue(split.Mask);
            if (split.Source != null && !split.Source.IsFormation) CameraSourceJson.Write(w, split.Source);
            w.WriteEndObject();
        }

        static string OverwriteName(OverwritePolicy policy) => policy == OverwritePolicy.Replace ? "replace" : "never";

        static double FormationParameter(FormationSettings f, string name)
        {
            switch (name)
            {
                case "elevationDegrees": return f.ElevationDegrees;
                case "startAzimuthDegrees": return f.StartAzimuthDegrees;
                case "topElevationDegrees": return f.TopElevationDegrees;
                case "bottomElevationDegrees": return f.BottomElevationDegrees;
                case "spiralRatio": return f.SpiralRatio;
                case "turns": return f.Turns;
                case "lowElevationDegrees": return f.LowElevationDegrees;
                case "highElevationDegrees": return f.HighElevationDegrees;
                default: throw new ArgumentOutOfRangeException(nameof(name), name, "not a numeric formation parameter");
            }
        }

        static void SetFormationParameter(FormationSettings f, string name, double value)
        {
            switch (name)
            {
                case "elevationDegrees": f.ElevationDegrees = value; break;
                case "startAzimuthDegrees": f.StartAzimuthDegrees = value; break;
                case "topElevationDegrees": f.TopElevationDegrees = value; break;
                case "bottomElevationDegrees": f.BottomElevationDegrees = value; break;
                case "spiralRatio": f.SpiralRatio = value; break;
                case "turns": f.Turns = value; break;
                case "lowElevationDegrees": f.LowElevationDegrees = value; break;
                case "highElevationDegrees": f.HighElevationDegrees = value; break;
                default: throw new ArgumentOutOfRangeException(nameof(name), name, "not a numeric formation parameter");
            }
        }

        /// <summary>
        /// Reads a config file. A folder, a missing file and an empty file are each one <see cref="SettingsFormatException"/>
        /// naming the file and the fix, not the runtime's text.
        /// </summary>
        public static SettingsReadResult ReadFile(string path)
        {
            if (Directory.Exists(path))
            {
                var configs = Directory.EnumerateFiles(path, "*.json").Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).Take(3).ToList();
                throw new SettingsFormatException(path, 0, 0, "", "is a folder, not a config file. Give the settings file itself" +
                    (configs.Count > 0 ? ", e.g. " + Path.Combine(path, configs[0]) + " (this folder holds " + string.Join(", ", configs) + ")." : " (a .json file, such as one saved by the window's Save config for batch…)."));
            }
            if (!File.Exists(path))
                throw new SettingsFormatException(path, 0, 0, "", "does not exist (looked for " + Path.GetFullPath(path) + "). Check the path; relative paths start at the current folder.");
            return Read(FileOps.ReadText(path), path);
        }

        /// <summary>
        /// Reads a config. Throws <see cref="SettingsFormatException"/> (with line and column) when the text is not
        /// JSON or a value has the wrong type; range checks are <see cref="SettingsValidator"/>'s job.
        /// </summary>
        public static SettingsReadResult Read(string text, string sourceName = "config")
        {
            JObject root;
            try
            {
                var token = JToken.Parse(text ?? "", new JsonLoadSettings
                {
                    LineInfoHandling = LineInfoHandling.Load,
                    DuplicatePropertyNameHandling = DuplicatePropertyNameHandling.Error,
                    CommentHandling = CommentHandling.Ignore,
                });
                root = token as JObject;
                if (root == null)
                    throw new SettingsFormatException(sourceName, Line(token), Column(token), "", "the config must be a JSON object { … }, not " + Describe(token) + ".");
            }
            catch (JsonReaderException e)
            {
                int line = e.LineNumber, column = e.LinePosition;
                var detail = JsonSyntaxHelp.Explain(e.Message, text, ref line, ref column);
                throw new SettingsFormatException(sourceName, line, column, "", detail);
            }

            var reader = new Reader(sourceName);
            foreach (var (line, column, what) in JsonLeniency.Find(text))
                reader.Warnings.Add(new ValidationProblem(sourceName + "(" + line + "," + column + ")", what,
                    "is not JSON; this plugin accepts it, but Python's json, jq and other tools refuse the file.",
                    "Remove it so that every tool can read the config."));
            var s = new DatasetSettings();
            reader.Object(root, "", new Dictionary<string, Action<JToken, string>>
            {
                ["schemaVersion"] = (t, p) => reader.SchemaVersion(t, p),
                ["name"] = (t, p) => s.Name = reader.String(t, p),
                ["outputFolder"] = (t, p) => s.OutputFolder = reader.String(t, p),
                ["scene"] = (t, p) => s.Scene = reader.String(t, p),
                ["target"] = (t, p) => s.Target = reader.String(t, p),
                ["camera"] = (t, p) => reader.Object(t, p, new Dictionary<string, Action<JToken, string>>
                {
                    ["verticalFovDegrees"] = (t2, p2) => s.Camera.VerticalFovDegrees = reader.Double(t2, p2),
                    ["nearClip"] = (t2, p2) => s.Camera.NearClip = reader.Double(t2, p2),
                    ["farClip"] = (t2, p2) => s.Camera.FarClip = reader.Double(t2, p2),
                    ["copyFromCamera"] = (t2, p2) => s.Camera.CopyFromCamera = reader.String(t2, p2),
                }),
                ["distance"] = (t, p) =>
                {
                    if (t.Type == JTokenType.String && string.Equals((string)t, "auto", StringComparison.OrdinalIgnoreCase))
                        s.AutoDistance = true;
                    else
                    {
                        s.AutoDistance = false;
                        s.Distance = reader.Double(t, p, "a number of Unity units or \"auto\"");
                    }
                },
                ["autoDistanceMargin"] = (t, p) => s.AutoDistanceMargin = reader.Double(t, p),
                ["width"] = (t, p) => s.Width = reader.Int(t, p),
                ["height"] = (t, p) => s.Height = reader.Int(t, p),
                ["supersampling"] = (t, p) => s.Supersampling = reader.Int(t, p),
                ["background"] = (t, p) =>
                {
                    var background = BackgroundSettings.Parse(reader.String(t, p));
                    if (background == null) throw reader.Error(t, p, "must be \"transparent\", \"sky\" or a colour \"#rrggbb\", not " + Describe(t) + ".");
                    s.Background = background;
                },
                [EvalProtocol.SettingsKey] = (t, p) =>
                {
                    var name = reader.String(t, p);
                    if (System.Array.IndexOf(EvalProtocol.BackgroundNames, name) < 0)
                        throw reader.Error(t, p, "must be one of " + string.Join(", ", EvalProtocol.BackgroundNames) + " (the background eval_protocol.json names), not " + Describe(t) + "." +
                            SpellingSuggestion.Sentence(name ?? "", EvalProtocol.BackgroundNames));
                    s.EvaluationBackground = name;
                },
                ["seed"] = (t, p) => s.Seed = reader.Long(t, p),
                ["overwrite"] = (t, p) =>
                {
                    var name = reader.String(t, p);
                    if (string.Equals(name, "never", StringComparison.OrdinalIgnoreCase)) s.Overwrite = OverwritePolicy.Never;
                    else if (string.Equals(name, "replace", StringComparison.OrdinalIgnoreCase)) s.Overwrite = OverwritePolicy.Replace;
                    else throw reader.Error(t, p, "must be \"never\" or \"replace\", not " + Describe(t) + ".");
                },
                ["loaders"] = (t, p) =>
                {
                    if (t.Type != JTokenType.Array) throw reader.Error(t, p, "must be a list such as [\"nerf\", \"instant-ngp\"], not " + Describe(t) + ".");
                    var loaders = TargetLoaders.None;
                    var index = 0;
                    foreach (var item in (JArray)t)
                    {
                        var itemPath = p + "[" + index++ + "]";
                        if (!TargetLoaderNames.TryParse(reader.String(item, itemPath), out var loader))
                            throw reader.Error(item, itemPath, "is not a known loader; use one of " + TargetLoaderNames.NameList() + "." +
                                SpellingSuggestion.Sentence(item.Type == JTokenType.String ? (string)item : "", TargetLoaderNames.NameList().Split(new[] { ", " }, StringSplitOptions.None)));
                        loaders |= loader;
                    }
                    s.Loaders = loaders;
                },
                ["normalisation"] = (t, p) =>
                {
                    if (!NormalisationModes.TryParse(reader.String(t, p), out var mode))
                        throw reader.Error(t, p, "must be one of " + NormalisationModes.NameList() + ", not " + Describe(t) + "." +
                            SpellingSuggestion.Sentence((string)t, NormalisationModes.All.Select(NormalisationModes.Name)));
                    s.Normalisation = mode;
                },
                ["normalisedTargetRadius"] = (t, p) => s.NormalisedTargetRadius = reader.Double(t, p),
                ["pointCloudPoints"] = (t, p) => s.PointCloudPoints = reader.Int(t, p),
                ["pointCloudRadius"] = (t, p) => s.PointCloudRadius = reader.Double(t, p),
                ["preflight"] = (t, p) => s.Preflight = reader.Bool(t, p),
                [GeometryPackSettingsJson.Key] = (t, p) => GeometryPackSettingsJson.Read(reader, t, p, s),
                [TimeSettingsJson.Key] = (t, p) => TimeSettingsJson.Read(reader, t, p, s.Time),
                [LabelSettingsJson.Key] = (t, p) => LabelSettingsJson.Read(reader, t, p, s.Labels),
                [LensSettings.Key] = (t, p) => LensSettingsJson.Read(reader, t, p, s.Lens),
                [ExposureSettingsJson.Key] = (t, p) => ExposureSettingsJson.Read(reader, t, p, s.Exposure),
                [MotionBlurSettingsJson.Key] = (t, p) => MotionBlurSettingsJson.Read(reader, t, p, s.MotionBlur),
                [SparseViewsSettings.Key] = (t, p) => s.SparseViews = SparseViewsSettings.Read(t, p, reader.Int, reader.Error),
                [HdrSettingsJson.Key] = (t, p) => HdrSettingsJson.Read(reader, t, p, s.Hdr),
                [MaterialPassSettingsJson.Key] = (t, p) => MaterialPassSettingsJson.Read(reader, t, p, s.Materials),
                [RelightingSettingsJson.Key] = (t, p) => RelightingSettingsJson.Read(reader, t, p, s.Relighting),
                [FlowSettingsJson.Key] = (t, p) => FlowSettingsJson.Read(reader, t, p, s.Flow),
                ["splits"] = (t, p) => reader.Object(t, p, DatasetSplits.All.ToDictionary(
                    split => DatasetSplits.Name(split),
                    split => (Action<JToken, string>)((t2, p2) => ReadSplit(reader, t2, p2, s.Split(split))))),
            });
            var result = new SettingsReadResult(s, reader.Warnings, root, sourceName);
            if (reader.Errors.Count > 0)
            {
                var e = reader.Errors.Count == 1 ? reader.Errors[0] : new SettingsFormatException(reader.Errors);
                e.Partial = result;
                throw e;
            }
            return result;
        }

        static void ReadSplit(Reader reader, JToken token, string path, SplitSettings split)
        {
            reader.Object(token, path, new Dictionary<string, Action<JToken, string>>
            {
                ["count"] = (t, p) => split.Count = reader.Int(t, p),
                ["formation"] = (t, p) => ReadFormation(reader, t, p, split.Formation),
                ["depth"] = (t, p) => split.Depth = reader.Extra(t, p),
                ["normal"] = (t, p) => split.Normal = reader.Extra(t, p),
                ["mask"] = (t, p) => split.Mask = reader.Bool(t, p),
                ["source"] = (t, p) => CameraSourceJson.Read(t, p, split.Source, reader.String, reader.Bool, reader.Int, (jt, jp) => reader.Double(jt, jp), reader.Error, reader.Object),
            });
        }

        static void ReadFormation(Reader reader, JToken token, string path, FormationSettings f)
        {
            if (token.Type != JTokenType.Object) throw reader.Error(token, path, "must be an object { \"kind\": … }, not " + Describe(token) + ".");
            var obj = (JObject)token;
            var kindToken = obj["kind"];
            if (kindToken == null) throw reader.Error(token, path + ".kind", "is missing; use one of " + FormationKinds.NameList() + ".");
            if (!FormationKinds.TryParse(reader.String(kindToken, path + ".kind"), out var kind))
                throw reader.Error(kindToken, path + ".kind", Describe(kindToken) + " is not a known formation; use one of " + FormationKinds.NameList() + "." +
                    SpellingSuggestion.Sentence((string)kindToken, FormationKinds.All.Select(FormationKinds.Name)));
            f.Kind = kind;
            var handlers = new Dictionary<string, Action<JToken, string>> { ["kind"] = (t, p) => { } };
            foreach (var name in FormationSettings.ParameterNames(kind))
            {
                var parameter = name;
                if (parameter == "upperHemisphereOnly") handlers[parameter] = (t, p) => f.UpperHemisphereOnly = reader.Bool(t, p);
                else handlers[parameter] = (t, p) => SetFormationParameter(f, parameter, reader.Double(t, p));
            }
            reader.Object(token, path, handlers, " (the formation \"" + FormationKinds.Name(kind) + "\" does not use it)");
        }

        static int Line(JToken t) => t is IJsonLineInfo info && info.HasLineInfo() ? info.LineNumber : 0;
        static int Column(JToken t) => t is IJsonLineInfo info && info.HasLineInfo() ? info.LinePosition : 0;

        internal static string Describe(JToken t)
        {
            switch (t.Type)
            {
                case JTokenType.String: return "\"" + (string)t + "\"";
                case JTokenType.Object: return "an object";
                case JTokenType.Array: return "a list";
                case JTokenType.Null: return "null";
                case JTokenType.Undefined: return "nothing (the value is missing)";
                default: return t.ToString(Formatting.None);
            }
        }


        /// <summary>Walks a config, typing values and collecting warnings with the place they come from.</summary>
        internal sealed class Reader
        {
            readonly string _source;
            public readonly List<ValidationProblem> Warnings = new List<ValidationProblem>();

            /// <summary>Every value of the wrong type: each key is read on its own, so one mistake hides no other.</summary>
            public readonly List<SettingsFormatException> Errors = new List<SettingsFormatException>();

            public Reader(string source) => _source = source;

            public SettingsFormatException Error(JToken t, string path, string detail) =>
                new SettingsFormatException(_source, Line(t), Column(t), path, detail);

            string Where(JToken t) => Line(t) > 0 ? " (line " + Line(t) + ", column " + Column(t) + ")" : "";

            public void Object(JToken token, string path, Dictionary<string, Action<JToken, string>> handlers, string unknownNote = "")
            {
                if (token.Type != JTokenType.Object) throw Error(token, path, "must be an object { … }, not " + Describe(token) + ".");
                foreach (var property in ((JObject)token).Properties())
                {
                    var childPath = path.Length == 0 ? property.Name : path + "." + property.Name;
                    if (handlers.TryGetValue(property.Name, out var handler))
                    {
                        try
                        {
                            handler(property.Value, childPath);
                        }
                        catch (SettingsFormatException e)
                        {
                            // Collected, not thrown: the user sees every wrong value in one pass, as with range checks.
                            Errors.Add(e);
                        }
                    }
                    else
                        Warnings.Add(new ValidationProblem(childPath, Describe(property.Value),
                            "is not a known setting" + unknownNote + Where(property) + " and is ignored.",
                            "Remove it or correct its spelling; the known keys here are: " + string.Join(", ", handlers.Keys) + "." +
                            SpellingSuggestion.Sentence(property.Name, handlers.Keys)));
                }
            }

            /// <summary>
            /// Reads an optional output's section (Core/Features/&lt;Feature&gt;/): its own keys through
            /// <paramref name="handlers"/>, plus the <c>"enabled": true|false</c> every feature section accepts
            /// (Documentation~/settings.md, "Optional outputs"). Returns that value, or null when the section does not
            /// give it — then the section's own keys decide, exactly as before the key existed.
            /// </summary>
            public bool? Feature(JToken token, string path, Dictionary<string, Action<JToken, string>> handlers)
            {
                bool? enabled = null;
                var all = new Dictionary<string, Action<JToken, string>> { [EnabledKey] = (t, p) => enabled = Bool(t, p) };
                foreach (var handler in handlers) all.Add(handler.Key, handler.Value);
                Object(token, path, all);
                return enabled;
            }

            /// <summary>The on/off key of every feature section.</summary>
            public const string EnabledKey = "enabled";

            /// <summary>
            /// Applies a section's <c>"enabled"</c> to a feature whose own keys also say on or off (lens <c>"model"</c>,
            /// exposure and time <c>"mode"</c>): false turns it off whatever they say; true must agree with them, since
            /// only they say which model or mode to use (<paramref name="offBecause"/> names the key that says off and
            /// how to turn it on).
            /// </summary>
            public void Switch(JToken section, string path, bool? enabled, bool onByOwnKeys, Action turnOff, string offBecause)
            {
                if (enabled == false) turnOff();
                else if (enabled == true && !onByOwnKeys)
                    throw Error(section[EnabledKey], path + "." + EnabledKey, "is true, but " + offBecause + ", or set \"enabled\": false.");
            }

            public void SchemaVersion(JToken t, string path)
            {
                var version = Int(t, path);
                if (version != DatasetSettings.CurrentSchemaVersion)
                    Warnings.Add(new ValidationProblem(path, version.ToString(System.Globalization.CultureInfo.InvariantCulture),
                        "differs from the version this plugin writes (" + DatasetSettings.CurrentSchemaVersion + ")" + Where(t) + "; settings it does not know are ignored.",
                        "Check the values after loading, then save the config again to update it."));
            }

            public string String(JToken t, string path)
            {
                if (t.Type != JTokenType.String) throw Error(t, path, "must be a string in quotes, not " + Describe(t) + ".");
                return (string)t;
            }

            public double Double(JToken t, string path, string expected = "a number")
            {
                if (JsonValues.TryNumber(t, out var number)) return number;
                // Validation, not the reader, reports NaN and infinity, so a file written while a field held one reads back.
                if (t.Type == JTokenType.String && double.TryParse((string)t, System.Globalization.NumberStyles.Float,
                        System.Globalization.CultureInfo.InvariantCulture, out var special) && (double.IsNaN(special) || double.IsInfinity(special)))
                    return special;
                throw Error(t, path, "must be " + expected + ", not " + Describe(t) + ".");
            }

            public long Long(JToken t, string path)
            {
                if (t.Type != JTokenType.Integer) throw Error(t, path, "must be a whole number, not " + Describe(t) + ".");
                if (!JsonValues.TryLong(t, out var value)) throw Error(t, path, "is too large; use a whole number from " + long.MinValue + " to " + long.MaxValue + ".");
                return value;
            }

            public int Int(JToken t, string path)
            {
                if (t.Type != JTokenType.Integer) throw Error(t, path, "must be a whole number, not " + Describe(t) + ".");
                if (!JsonValues.TryInt(t, out var value)) throw Error(t, path, "is far too large for this setting.");
                return value;
            }

            public bool Bool(JToken t, string path)
            {
                if (t.Type != JTokenType.Boolean) throw Error(t, path, "must be true or false, not " + Describe(t) + ".");
                return (bool)t;
            }

            /// <summary>Parses a name to one of its values, or reports "must be one of …" with a spelling suggestion.</summary>
            public delegate bool NameParser<T>(string name, out T value);

            /// <summary>
            /// One of a set of names (a mode, a rule, a source): <paramref name="tryParse"/>'s value, or "must be one of
            /// <paramref name="nameList"/>." with the closest of <paramref name="names"/> when one is near.
            /// </summary>
            public T Name<T>(JToken t, string path, NameParser<T> tryParse, string nameList, IEnumerable<string> names)
            {
                if (!tryParse(String(t, path), out var value))
                    throw Error(t, path, "must be one of " + nameList + "." + SpellingSuggestion.Sentence((string)t, names));
                return value;
            }

            public ExtraOutput Extra(JToken t, string path)
            {
                if (!ExtraOutputs.TryParse(String(t, path), out var output))
                    throw Error(t, path, "must be \"none\", \"png\", \"exr\" or \"png+exr\", not " + Describe(t) + "." +
                        SpellingSuggestion.Sentence((string)t, new[] { "none", "png", "exr", "png+exr" }));
                return output;
            }
        }
    }
}
