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
    /// The part of a Blender-format dataset that evaluation reads: one split's frames (<see cref="DatasetFolder"/>),
    /// the pinhole from <c>camera_angle_x</c> (and <c>cx</c>, <c>cy</c> when written), the depth scale, and
    /// <c>dataset_config.json</c> when present. Extras are the files the frame's keys name — never guessed from the
    /// image's name, as <c>check</c> does too: nerf_synthetic's own <c>r_0_depth_0000.png</c> are 8-bit pictures, not
    /// depth — and used only when every frame has them.
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

        /// <summary>
        /// Why a pass the renders carry is not scored, for the report's note: no frame names a file of it (keys only:
        /// a file is never guessed from the image's name), or only some frames name a usable PNG.
        /// </summary>
        public string Unscored(string what, string key, Func<EvaluationFrame, string> path)
        {
            var with = Frames.Count(f => path(f) != null);
            return with == 0
                ? "the frames of the dataset's " + Split + " split name no " + what + " file (" + key + "; files are never guessed from the image names)"
                : "only " + with + " of " + Frames.Count + " frames of the dataset's " + Split + " split name a usable " + what + " PNG";
        }

        /// <summary>Focal length in pixels for an image <paramref name="width"/> wide: 0.5·W / tan(0.5·camera_angle_x).</summary>
        public double Focal(int width) => 0.5 * width / Math.Tan(0.5 * CameraAngleX);

        /// <summary>The same dataset with only the frames at <paramref name="indices"/> (of <see cref="Frames"/>), in that order: a split file's test views.</summary>
        public EvaluationDataset Subset(IReadOnlyList<int> indices)
        {
            var copy = (EvaluationDataset)MemberwiseClone();
            copy.Frames = indices.Select(i => Frames[i]).ToList();
            return copy;
        }

        public static EvaluationDataset Read(string folder, string split)
        {
            if (string.IsNullOrEmpty(folder) || !Directory.Exists(folder))
                throw Problem("<dataset>", folder ?? "", "is not an existing folder.", "Pass the dataset folder (the one holding transforms_" + split + ".json).");
            var root = Path.GetFullPath(folder);
            var jsonPath = Path.Combine(root, DatasetLayout.TransformsFileName(split));
            if (!File.Exists(jsonPath))
                throw Problem("<dataset>", root, "has no " + DatasetLayout.TransformsFileName(split) + ".", "Pass a Blender-format dataset folder, or another split with --split.");
            DatasetSplitFile doc;
            try { doc = DatasetFolder.ReadSplit(root, split, DatasetReadMode.Strict); }
            catch (SettingsFormatException e) { throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, e.Message, "Fix or regenerate the file."); }
            if (doc.Problems.Count > 0) throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, string.Join(" ", doc.Problems), "Run nerf-dataset validate on the dataset and fix what it reports.");
            if (!(doc.CameraAngleX > 0 && doc.CameraAngleX < Math.PI)) throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, "has no camera_angle_x in (0, π).", "Write the horizontal field of view in radians.");
            if (doc.Frames.Count == 0) throw Problem(DatasetLayout.TransformsFileName(split), jsonPath, "lists no frames, so there is nothing to evaluate.", "Pick a split with views: --split test (or train, val).");

            var result = new EvaluationDataset { Root = root, Split = split, CameraAngleX = doc.CameraAngleX.Value, DepthScale = doc.IntegerDepthScale ?? doc.DepthUnitScaleFactor ?? 0.001 };
            if (doc.Intrinsics.Cx is double cx && doc.Intrinsics.Cy is double cy) { result.Cx = cx; result.Cy = cy; }
            var frames = new List<EvaluationFrame>();
            foreach (var f in doc.Frames)
            {
                var field = DatasetLayout.TransformsFileName(split) + " frame " + f.Index;
                if (f.Problems.Count > 0) throw Problem(field, f.FilePath ?? "", string.Join(" ", f.Problems), "Run nerf-dataset validate on the dataset.");
                var image = Png(f.Image);
                if (image == null) throw Problem(field, f.FilePath, "names no image inside the dataset (looked for the path and the path + .png).", "Run nerf-dataset validate on the dataset.");
                frames.Add(new EvaluationFrame
                {
                    Index = f.Index,
                    FilePath = f.FilePath,
                    CameraToWorld = f.TransformMatrix.Value,
                    ImagePath = image,
                    // Keys only: the instant-ngp key, else nerfstudio's (this plugin writes both, naming one file).
                    DepthPath = Png(f.Named("depth_path")) ?? Png(f.Named("depth_file_path")),
                    NormalPath = Png(f.Named("normal_path")),
                    MaskPath = Png(f.Named("mask_path")),
                    TimeStep = f.Time.Step,
                    Time = f.Time.Time,
                });
            }
            result.Frames = frames;
            // A malformed config is ignored (a dataset without one is evaluated too); an unreadable one fails the read.
            result.Config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            return result;
        }

        /// <summary>The absolute path of a PNG the frame names inside the dataset, or null (absent, outside, missing, or not a .png).</summary>
        static string Png(DatasetFile file) =>
            file != null && file.Exists && file.FullPath.EndsWith(".png", StringComparison.OrdinalIgnoreCase) ? file.FullPath : null;

        static InvalidParameterException Problem(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
