using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Each trainer's output folder, read from the files the trainer itself writes (sources and lines in
    /// Documentation~/maintainers/splat-placement.md): graphdeco 3DGS's model folder, nerfstudio's run folder, gsplat's
    /// simple_trainer result folder.
    /// </summary>
    public static class TrainerFolders
    {
        /// <summary>One trainer a folder looks like, and the files that say so.</summary>
        public sealed class Evidence
        {
            public Evidence(string trainer, string files)
            {
                Trainer = trainer;
                Files = files;
            }

            public string Trainer { get; }
            public string Files { get; }
        }

        public const string GaussianSplattingConfig = "cfg_args";
        public const string NerfstudioConfig = "config.yml";
        public const string NerfstudioTransforms = "dataparser_transforms.json";
        public const string GsplatConfig = "cfg.yml";
        public const string NerfstudioPly = "splat.ply";

        /// <summary>Every trainer whose files are in <paramref name="folder"/>, in <see cref="TrainedModel.Trainers"/> order.</summary>
        public static List<Evidence> Detect(string folder)
        {
            var found = new List<Evidence>();
            var iterations = Iterations(folder);
            var cfgArgs = File.Exists(Path.Combine(folder, GaussianSplattingConfig));
            if (iterations.Count > 0 || cfgArgs)
                found.Add(new Evidence(TrainedModel.GaussianSplatting, string.Join(", ", new[]
                {
                    cfgArgs ? GaussianSplattingConfig : null,
                    iterations.Count > 0 ? "point_cloud/" + Path.GetFileName(Path.GetDirectoryName(iterations.Last().Path)) + "/point_cloud.ply" : null,
                }.Where(s => s != null))));
            if (File.Exists(Path.Combine(folder, NerfstudioTransforms)))
                found.Add(new Evidence(TrainedModel.Nerfstudio, NerfstudioTransforms + (File.Exists(Path.Combine(folder, NerfstudioConfig)) ? " and " + NerfstudioConfig : "")));
            if (File.Exists(Path.Combine(folder, GsplatConfig)))
                found.Add(new Evidence(TrainedModel.Gsplat, GsplatConfig));
            return found;
        }

        // ---- graphdeco 3DGS ----

        /// <summary>
        /// <c>point_cloud/iteration_&lt;N&gt;/point_cloud.ply</c>, the highest N by number (Scene.save writes them; 3DGS's
        /// own searchForMaxIteration compares numbers too). The frame is the dataset's: both readers keep the world.
        /// </summary>
        public static TrainedModel GaussianSplattingModel(string folder, string ply)
        {
            var notes = new List<string>();
            if (ply == null)
            {
                var iterations = Iterations(folder);
                if (iterations.Count == 0)
                    throw TrainedModel.Refuse("--model", folder, "is a 3DGS model folder without point_cloud/iteration_<N>/point_cloud.ply: training has not saved a model yet.",
                        "Wait for train.py to save (it saves at --save_iterations, by default 7000 and 30000), or pass the PLY with --ply.");
                ply = iterations.Last().Path;
                if (iterations.Count > 1) notes.Add("placed iteration " + iterations.Last().Number + ", the highest of " + string.Join(", ", iterations.Select(i => i.Number)) + ".");
            }
            return new TrainedModel(TrainedModel.GaussianSplatting, folder, ply, Matrix4x4d.Identity,
                "the dataset's own frame (3DGS's Blender and COLMAP readers keep the world as written)", notes);
        }

        /// <summary>The saved iterations (point_cloud.ply present), by number, lowest first.</summary>
        static List<(long Number, string Path)> Iterations(string folder)
        {
            var root = Path.Combine(folder, "point_cloud");
            var result = new List<(long, string)>();
            if (!Directory.Exists(root)) return result;
            foreach (var dir in Directory.GetDirectories(root))
            {
                var name = Path.GetFileName(dir);
                if (!name.StartsWith("iteration_", StringComparison.Ordinal)) continue;
                var digits = name.Substring("iteration_".Length);
                if (digits.Length == 0 || !digits.All(c => c >= '0' && c <= '9') || !long.TryParse(digits, NumberStyles.None, CultureInfo.InvariantCulture, out var n)) continue;
                var file = Path.Combine(dir, "point_cloud.ply");
                if (File.Exists(file)) result.Add((n, file));
            }
            return result.OrderBy(r => r.Item1).ToList();
        }

        // ---- nerfstudio (splatfacto) ----

        /// <summary>
        /// nerfstudio's run folder: <c>dataparser_transforms.json</c> holds the 3×4 transform T and scale s its dataparser
        /// applied, x_ns = s·T·[x, 1]; <c>ns-export gaussian-splat</c> writes the Gaussians' means as they are, in that frame.
        /// </summary>
        public static TrainedModel NerfstudioRun(string folder, string ply)
        {
            var notes = new List<string>();
            var transformsPath = Path.Combine(folder, NerfstudioTransforms);
            if (!File.Exists(transformsPath))
                throw TrainedModel.Refuse("--model", folder, "has no " + NerfstudioTransforms + ", which ns-train writes into the run folder when training starts.",
                    "Pass the run folder (outputs/<name>/splatfacto/<timestamp>), the one holding config.yml.");
            var method = ConfigValue(Path.Combine(folder, NerfstudioConfig), "method_name");
            if (method != null && !method.StartsWith("splatfacto", StringComparison.Ordinal))
                throw TrainedModel.Refuse("--model", folder, "is a nerfstudio " + method + " run (config.yml method_name), not a Gaussian splat.", "Train splatfacto (ns-train splatfacto ...) and pass its run folder.");
            var outputToTrainer = ReadDataparserTransform(transformsPath);
            if (ply == null)
            {
                ply = FindNerfstudioPly(folder);
                if (ply == null)
                    throw TrainedModel.Refuse("--model", folder, "holds no " + NerfstudioPly + " (looked in the run folder and two levels of subfolders).",
                        "Export it with ns-export gaussian-splat --load-config " + Path.Combine(folder, NerfstudioConfig) + " --output-dir " + Path.Combine(folder, "exports") + ", or pass --ply <file> when --output-dir was elsewhere.");
                notes.Add("found " + NerfstudioPly + " at " + ply + ".");
            }
            return new TrainedModel(TrainedModel.Nerfstudio, folder, ply, outputToTrainer,
                "nerfstudio's dataparser frame (" + NerfstudioTransforms + ": x_ns = scale · transform · [x, 1]; ns-export does not undo it)", notes);
        }

        /// <summary><c>{"transform": 3×4, "scale": s}</c> as the 4×4 s·[T; 0 0 0 1/s] (the last row stays 0 0 0 1).</summary>
        public static Matrix4x4d ReadDataparserTransform(string path)
        {
            JObject json;
            try { json = JObject.Parse(FileOps.ReadText(path)); }
            catch (Newtonsoft.Json.JsonException e) { throw TrainedModel.Refuse(NerfstudioTransforms, path, "is not valid JSON: " + e.Message, "Train again; ns-train writes this file when training starts."); }
            var rows = json["transform"] as JArray;
            var values = new double[3][];
            var ok = rows != null && rows.Count == 3 && JsonValues.TryNumber(json["scale"], out _);
            for (var r = 0; ok && r < 3; r++)
            {
                ok = rows[r] is JArray row && row.Count == 4;
                if (!ok) break;
                values[r] = new double[4];
                for (var c = 0; ok && c < 4; c++) ok = JsonValues.TryNumber(rows[r][c], out values[r][c]);
            }
            JsonValues.TryNumber(json["scale"], out var scale);
            if (!ok || !(scale > 0) || double.IsInfinity(scale))
                throw TrainedModel.Refuse(NerfstudioTransforms, path, "is not {\"transform\": 3 rows of 4 numbers, \"scale\": a positive number}.", "Train again; ns-train writes this file when training starts.");
            var m = AffineMaps.Scaled(AffineMaps.FromRows3x4(values), scale);
            if (m.Determinant3x3 == 0) throw TrainedModel.Refuse(NerfstudioTransforms, path, "holds a transform that cannot be inverted.", "Train again; ns-train writes this file when training starts.");
            return m;
        }

        static string FindNerfstudioPly(string folder)
        {
            var direct = Path.Combine(folder, NerfstudioPly);
            if (File.Exists(direct)) return direct;
            foreach (var sub in Directory.GetDirectories(folder).OrderBy(d => d, StringComparer.Ordinal))
            {
                var inSub = Path.Combine(sub, NerfstudioPly);
                if (File.Exists(inSub)) return inSub;
                foreach (var subSub in Directory.GetDirectories(sub).OrderBy(d => d, StringComparer.Ordinal))
                    if (File.Exists(Path.Combine(subSub, NerfstudioPly))) return Path.Combine(subSub, NerfstudioPly);
            }
            return null;
        }

        // ---- gsplat (examples/simple_trainer.py) ----

        /// <summary>
        /// gsplat's result folder: <c>cfg.yml</c> (yaml.dump of the run's Config) and <c>ply/point_cloud_&lt;step&gt;.ply</c>
        /// (written with <c>--save-ply</c>), the highest step. With <c>normalize_world_space</c> off the frame is the
        /// COLMAP model's, which is the dataset's; with it on (gsplat's default) see <see cref="GsplatNormalisation"/>.
        /// </summary>
        public static TrainedModel GsplatResult(string folder, string ply)
        {
            var notes = new List<string>();
            var cfg = Path.Combine(folder, GsplatConfig);
            if (ply == null)
            {
                var steps = GsplatPlys(folder);
                if (steps.Count == 0)
                    throw TrainedModel.Refuse("--model", folder, "is a gsplat result folder without ply/point_cloud_<step>.ply.",
                        "Train with --save-ply (simple_trainer.py writes the PLY at --ply-steps and the last step), or pass the PLY with --ply.");
                ply = steps.Last().Path;
                if (steps.Count > 1) notes.Add("placed step " + steps.Last().Number + ", the highest of " + string.Join(", ", steps.Select(s => s.Number)) + ".");
            }
            var normalise = ConfigValue(cfg, "normalize_world_space");
            if (normalise == null || normalise == "true")
                return GsplatNormalisation.Place(folder, ply, ConfigValue(cfg, "data_dir"), normalise == null, notes);
            if (normalise != "false")
                throw TrainedModel.Refuse(GsplatConfig + ": normalize_world_space", normalise, "is neither true nor false.", "Pass the result folder simple_trainer.py wrote, its cfg.yml unchanged.");
            notes.Add("gsplat trained with normalize_world_space off: its frame is the COLMAP model's, the dataset's own.");
            return new TrainedModel(TrainedModel.Gsplat, folder, ply, Matrix4x4d.Identity, "the dataset's own frame (gsplat with normalize_world_space off keeps the COLMAP world)", notes);
        }

        static List<(long Number, string Path)> GsplatPlys(string folder)
        {
            var dir = Path.Combine(folder, "ply");
            var result = new List<(long, string)>();
            if (!Directory.Exists(dir)) return result;
            foreach (var file in Directory.GetFiles(dir, "point_cloud_*.ply"))
            {
                var digits = Path.GetFileNameWithoutExtension(file).Substring("point_cloud_".Length);
                if (digits.Length > 0 && digits.All(c => c >= '0' && c <= '9') && long.TryParse(digits, NumberStyles.None, CultureInfo.InvariantCulture, out var n)) result.Add((n, file));
            }
            return result.OrderBy(r => r.Item1).ToList();
        }

        /// <summary>
        /// A top-level <c>key: value</c> of a YAML file written by Python's yaml.dump (gsplat's cfg.yml, nerfstudio's
        /// config.yml), unquoted and trimmed; null when the file or the key is missing. Nested blocks are skipped.
        /// </summary>
        public static string ConfigValue(string path, string key)
        {
            if (!File.Exists(path)) return null;
            foreach (var line in FileOps.ReadText(path).Split('\n'))
            {
                if (line.Length == 0 || line[0] == ' ' || line[0] == '-' || line[0] == '#') continue;
                if (!line.StartsWith(key + ":", StringComparison.Ordinal)) continue;
                var value = line.Substring(key.Length + 1).Trim().TrimEnd('\r');
                if (value.Length >= 2 && (value[0] == '\'' || value[0] == '"') && value[value.Length - 1] == value[0])
                    value = value.Substring(1, value.Length - 2).Replace("''", "'");
                return value;
            }
            return null;
        }
    }
}
