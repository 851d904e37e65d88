using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>One frame of a split as evaluation needs it: pose, ground-truth image and the optional data images.</summary>
    public sealed class EvaluationFrame
    {
        public int Index { get; internal set; }
        public string FilePath { get; internal set; }
        public Matrix4x4d CameraToWorld { get; internal set; }
        public string ImagePath { get; internal set; }
        public string DepthPath { get; internal set; }
        public string NormalPath { get; internal set; }
        public string MaskPath { get; internal set; }

        /// <summary>The frame's <c>time_step</c> (a dynamic capture's step k), or null.</summary>
        public int? TimeStep { get; internal set; }

        /// <summary>The frame's <c>time</c> (normalised, in [0, 1]), or null.</summary>
        public double? Time { get; internal set; }
    }

    /// <summary>
    /// The part of a Blender-format dataset that evaluation reads: one split's frames (<see cref="TransformsReader"/>),
    /// the pinhole from <c>camera_angle_x</c> (and <c>cx</c>, <c>cy</c> when written), the depth scale, and
    /// <c>dataset_config.json</c> when present. Extras are found by the frame's keys or, failing those, by this plugin's
    /// names next to the image (<c>r_0_depth_0000.png</c> …), and used only when every frame has them.
    /// </summary>
    public sealed class EvaluationDataset
    {
        public string Root { get; private set; }
        public string Split { get; private set; }
        public IReadOnlyList<EvaluationFrame> Frames { get; private set; }
        public double CameraAngleX { get; private set; }
        public double? Cx { get; private set; }
        public double? Cy { get; private set; }

        /// <summary>Output units per depth-PNG step (<c>integer_depth_scale</c>, 0.001 by default).</summary>
        public double DepthScale { get; private set; }

        /// <summary>The dataset's <c>dataset_config.json</c>, or null when it has none or it is not JSON.</summary>
        public DatasetConfig Config { get; private set; }

        public bool HasDepth => Frames.Count > 0 && Frames.All(f => f.DepthPath != null);
        public bool HasNormals => Frames.Count > 0 && Frames.All(f => f.NormalPath != null);
        public bool HasMasks => Frames.Count > 0 && Frames.All(f => f.MaskPath != null);

        /// <summary>Focal length in pixels for an image <paramref name="width"/> wide: 0.5·W / tan(0.5·camera_angle_x).</summary>
        public double Focal(int width) => 0.5 * width / Math.Tan(0.5 * CameraAngleX);

        public static EvaluationDataset Read(string folder, string split)
        {
            if (string.IsNullOrEmpty(folder) || !Directory.Exists(folder))
                throw Problem("<dataset>", folder ?? "", "is not an existing folder.", "Pass the dataset folder (the one holding transforms_" + split + ".json).");
            var root = Path.GetFullPath(folder);
            var jsonPath = Path.Combine(root, DatasetLayout.TransformsFileName(split));
            if (!File.Exists(jsonPath))
                throw Problem("<dataset>", root, "has no " + DatasetLayout.TransformsFileName(split) + ".", "Pass a Blender-format dataset folder, or another split with --split.");
            TransformsDocument doc;
            try { doc = TransformsReader.ReadFile(jsonPath); }
            catch (SettingsFormatException e) { throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, e.Message, "Fix or regenerate the file."); }
            if (doc.Problems.Count > 0) throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, string.Join(" ", doc.Problems), "Run nerf-dataset validate on the dataset and fix what it reports.");
            if (!(doc.CameraAngleX > 0 && doc.CameraAngleX < Math.PI)) throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, "has no camera_angle_x in (0, π).", "Write the horizontal field of view in radians.");
            if (doc.Frames.Count == 0) throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, "lists no frames, so there is nothing to evaluate.", "Pick a split with views: --split test (or train, val).");

            var result = new EvaluationDataset { Root = root, Split = split, CameraAngleX = doc.CameraAngleX.Value, DepthScale = doc.IntegerDepthScale ?? doc.DepthUnitScaleFactor ?? 0.001 };
            var json = JObject.Parse(FileOps.ReadText(jsonPath));
            if (JsonValues.TryNumber(json["cx"], out var cx) && JsonValues.TryNumber(json["cy"], out var cy)) { result.Cx = cx; result.Cy = cy; }
            var frames = new List<EvaluationFrame>();
            var jsonFrames = json["frames"] as JArray;
            foreach (var f in doc.Frames)
            {
                var frameJson = jsonFrames != null && f.Index >= 0 && f.Index < jsonFrames.Count ? jsonFrames[f.Index] as JObject : null;
                var field = DatasetLayout.TransformsFileName(split) + " frame " + f.Index;
                if (f.Problems.Count > 0) throw Problem(field, f.FilePath ?? "", string.Join(" ", f.Problems), "Run nerf-dataset validate on the dataset.");
                var image = Resolve(root, f.FilePath, true);
                if (image == null) throw Problem(field, f.FilePath, "names no image inside the dataset (looked for the path and the path + .png).", "Run nerf-dataset validate on the dataset.");
                var stem = image.Substring(0, image.Length - 4);
                frames.Add(new EvaluationFrame
                {
                    Index = f.Index,
                    FilePath = f.FilePath,
                    CameraToWorld = f.TransformMatrix.Value,
                    ImagePath = image,
                    DepthPath = Extra(root, f, "depth_path", stem + DatasetLayout.Suffix(DatasetFileKind.DepthPng)),
                    NormalPath = Extra(root, f, "normal_path", stem + DatasetLayout.Suffix(DatasetFileKind.NormalPng)),
                    MaskPath = Extra(root, f, "mask_path", stem + DatasetLayout.Suffix(DatasetFileKind.MaskPng)),
                    TimeStep = frameJson?[TimeKeys.Step]?.Type == JTokenType.Integer ? (int?)(int)frameJson[TimeKeys.Step] : null,
                    Time = JsonValues.TryNumber(frameJson?[TimeKeys.Time], out var time) ? (double?)time : null,
                });
            }
            result.Frames = frames;
            // A malformed config is ignored (a dataset without one is evaluated too); an unreadable one fails the read.
            result.Config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            return result;
        }

        static string Extra(string root, TransformsFrame frame, string key, string conventional)
        {
            if (frame.ExtraFiles.TryGetValue(key, out var named))
            {
                var path = Resolve(root, named, false);
                if (path != null) return path;
            }
            return File.Exists(conventional) ? conventional : null;
        }

        static string Resolve(string root, string relative, bool addPng)
        {
            if (string.IsNullOrEmpty(relative)) return null;
            var inside = PathSafety.Inside(root, relative, out _);
            if (inside == null) return null;
            if (File.Exists(inside) && inside.EndsWith(".png", StringComparison.OrdinalIgnoreCase)) return inside;
            if (addPng && File.Exists(inside + ".png")) return inside + ".png";
            return null;
        }

        static InvalidParameterException Problem(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
