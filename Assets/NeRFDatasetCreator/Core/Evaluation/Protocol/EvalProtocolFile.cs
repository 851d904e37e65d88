using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>eval_protocol.json</c>: writing it (<see cref="Text"/>) and reading it back (<see cref="Read"/>). Only
    /// <c>background</c>, <c>background_rgb</c>, <c>splits</c> and <c>resolution_factor</c> are read; the other keys
    /// say how the protocol is realised and are rewritten from these (Documentation~/output-format.md).
    /// </summary>
    public static class EvalProtocolFile
    {
        public const string FileName = "eval_protocol.json";

        public const string About = "How this dataset is meant to be trained and scored. nerf-dataset evaluate reads it by default (background, evaluation split, resolution factor) and refuses a contradicting --background; nerf-dataset check --model compares it with a trainer's written config.";

        public static string Text(EvalProtocol p)
        {
            var json = new JObject
            {
                ["generator"] = PluginInfo.Name,
                ["pluginVersion"] = PluginInfo.Version,
                ["about"] = About,
                ["background"] = p.Background,
                ["background_rgb"] = new JArray(p.R, p.G, p.B),
                ["dataset_background"] = p.DatasetBackground,
                ["splits"] = new JObject { ["train"] = new JArray(p.TrainSplits), ["evaluation"] = p.EvaluationSplit, ["validation"] = p.ValidationSplit },
                ["resolution_factor"] = p.ResolutionFactor,
                ["compositing"] = EvalProtocolTrainers.Compositing,
                ["ssim"] = EvalProtocolTrainers.Ssim,
                ["lpips"] = new JObject { ["network"] = EvalProtocolTrainers.LpipsNetwork, ["input_range"] = EvalProtocolTrainers.LpipsRange },
                ["trainer_flags"] = new JObject(EvalProtocolTrainers.Flags(p).Select(f => new JProperty(f.Key, f.Value))),
            };
            return json.ToString(Formatting.Indented).Replace("\r\n", "\n") + "\n";
        }

        /// <summary>
        /// The protocol in <paramref name="datasetRoot"/>, or null when it has no <c>eval_protocol.json</c>. A file that
        /// is not a protocol (not JSON, an unknown background, a colour out of range) is an <see cref="InvalidParameterException"/>
        /// naming the file and the key: a protocol is never guessed past.
        /// </summary>
        public static EvalProtocol Read(string datasetRoot)
        {
            var path = Path.Combine(datasetRoot, FileName);
            if (!File.Exists(path)) return null;
            JObject o;
            try { o = JToken.Parse(FileOps.ReadText(path)) as JObject; }
            catch (JsonException e) { throw Bad(path, "", "is not valid JSON (" + e.Message + ")."); }
            catch (IOException e) { throw Bad(path, "", "cannot be read (" + e.Message + ")."); }
            catch (UnauthorizedAccessException e) { throw Bad(path, "", "cannot be read (" + e.Message + ")."); }
            if (o == null) throw Bad(path, "", "is not a JSON object.");

            var p = new EvalProtocol();
            var background = o["background"];
            if (!(background is JValue b && b.Type == JTokenType.String) || Array.IndexOf(EvalProtocol.BackgroundNames, (string)background) < 0)
                throw Bad(path, "background", "is " + Shown(background) + ", not one of " + string.Join(", ", EvalProtocol.BackgroundNames) + ".");
            p.Background = (string)background;
            var rgb = o["background_rgb"] as JArray;
            if (rgb == null || rgb.Count != 3 || rgb.Any(c => c.Type != JTokenType.Integer || (long)c < 0 || (long)c > 255))
                throw Bad(path, "background_rgb", "is " + Shown(o["background_rgb"]) + ", not three whole numbers 0–255 (the 8-bit sRGB colour scored over).");
            p.R = (byte)(long)rgb[0];
            p.G = (byte)(long)rgb[1];
            p.B = (byte)(long)rgb[2];
            if (o["dataset_background"] is JValue d && d.Type == JTokenType.String) p.DatasetBackground = (string)d;
            if (o["splits"] is JObject splits)
            {
                if (splits["train"] is JArray train && train.Count > 0 && train.All(IsSplit)) p.TrainSplits = train.Select(t => (string)t).ToList();
                else if (splits["train"] != null) throw Bad(path, "splits.train", "is " + Shown(splits["train"]) + ", not a list of train, val, test.");
                if (splits["evaluation"] != null)
                {
                    if (!IsSplit(splits["evaluation"])) throw Bad(path, "splits.evaluation", "is " + Shown(splits["evaluation"]) + ", not train, val or test.");
                    p.EvaluationSplit = (string)splits["evaluation"];
                }
                if (IsSplit(splits["validation"])) p.ValidationSplit = (string)splits["validation"];
            }
            var factor = o["resolution_factor"];
            if (factor != null)
            {
                if (factor.Type != JTokenType.Integer || (long)factor < 1 || (long)factor > 64)
                    throw Bad(path, "resolution_factor", "is " + Shown(factor) + ", not a whole number from 1 to 64.");
                p.ResolutionFactor = (int)(long)factor;
            }
            return p;
        }

        /// <summary>The protocol a dataset without the file would have been given: from dataset_config.json's background (and <see cref="EvalProtocol.SettingsKey"/>), else white.</summary>
        public static EvalProtocol Derived(string datasetRoot)
        {
            var config = DatasetConfig.Read(datasetRoot).Config;
            var settings = config?.Background;
            string chosen = null;
            if (config?.Settings?[EvalProtocol.SettingsKey] is JValue v && v.Type == JTokenType.String) chosen = (string)v;
            // A recorded choice that no longer fits is not this reader's to refuse: the default is used.
            if (EvalProtocol.Problem(settings, chosen) != null) chosen = null;
            return EvalProtocol.For(settings, chosen);
        }

        static bool IsSplit(JToken t) => t is JValue v && v.Type == JTokenType.String && DatasetSplits.Names.Contains((string)v);

        static string Shown(JToken t) => t == null ? "missing" : t.ToString(Formatting.None);

        static InvalidParameterException Bad(string path, string key, string reason) =>
            new InvalidParameterException(new[] { new ValidationProblem(key.Length == 0 ? FileName : FileName + ": " + key, path, reason,
                "Fix the file, or delete it to fall back to the default (white for a transparent dataset, its own colour for a solid one).") });
    }
}
