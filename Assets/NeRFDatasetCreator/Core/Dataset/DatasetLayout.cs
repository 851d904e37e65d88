using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Names inside a dataset folder, exactly nerf_synthetic's: <c>transforms_&lt;split&gt;.json</c>,
    /// <c>&lt;split&gt;/r_&lt;i&gt;.png</c> (no zero padding), extras <c>r_&lt;i&gt;_depth_0000.png</c> and
    /// <c>r_&lt;i&gt;_normal_0000.png</c> (nerf_synthetic's suffix), plus <c>r_&lt;i&gt;_mask_0000.png</c> and
    /// <c>.exr</c> variants. Relative paths use forward slashes on every OS.
    /// </summary>
    public static class DatasetLayout
    {
        public const string ConfigFileName = "dataset_config.json";
        public const string RigPreviewFileName = "rig_preview.ply";

        /// <summary>The label table of a capture with instance/semantic maps (Documentation~/labels.md).</summary>
        public const string LabelsFileName = "labels.json";

        /// <summary>A split's colour-coded label preview, for looking at, not for training: <c>labels_preview_train.png</c>.</summary>
        public static string LabelsPreviewFileName(string splitName) => "labels_preview_" + splitName + ".png";

        public static string TransformsFileName(DatasetSplit split) => TransformsFileName(DatasetSplits.Name(split));

        /// <summary><c>transforms_&lt;split&gt;.json</c> for a split name as the files spell it ("train").</summary>
        public static string TransformsFileName(string splitName) => "transforms_" + splitName + ".json";

        /// <summary>The view's file stem, <c>r_7</c>.</summary>
        public static string Stem(int index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index), index, "a view index is never negative");
            return "r_" + index.ToString(CultureInfo.InvariantCulture);
        }

        /// <summary>The <c>file_path</c> value: <c>./train/r_7</c>, without extension (loaders append ".png").</summary>
        public static string FramePath(DatasetSplit split, int index) => "./" + DatasetSplits.Name(split) + "/" + Stem(index);

        /// <summary>The file's path relative to the dataset folder, e.g. <c>test/r_7_depth_0000.png</c>.</summary>
        public static string RelativePath(DatasetSplit split, int index, DatasetFileKind kind) =>
            DatasetSplits.Name(split) + "/" + Stem(index) + Suffix(kind);

        /// <summary>The file's path as a per-frame key holds it, relative to the transforms file: <c>./test/r_7_depth_0000.png</c>.</summary>
        public static string FrameKeyPath(DatasetSplit split, int index, DatasetFileKind kind) => "./" + RelativePath(split, index, kind);

        public static string Suffix(DatasetFileKind kind)
        {
            switch (kind)
            {
                case DatasetFileKind.Color: return ".png";
                case DatasetFileKind.DepthPng: return "_depth_0000.png";
                case DatasetFileKind.DepthExr: return "_depth_0000.exr";
                case DatasetFileKind.NormalPng: return "_normal_0000.png";
                case DatasetFileKind.NormalExr: return "_normal_0000.exr";
                case DatasetFileKind.MaskPng: return "_mask_0000.png";
                case DatasetFileKind.InstancePng: return "_instance_0000.png";
                case DatasetFileKind.SemanticPng: return "_semantic_0000.png";
                case DatasetFileKind.CleanColor: return "_clean.png";
                case DatasetFileKind.SharpPng: return "_sharp_0000.png";
                case DatasetFileKind.HdrExr: return "_hdr.exr";
                case DatasetFileKind.AlbedoExr: return "_albedo.exr";
                case DatasetFileKind.AlbedoPng: return "_albedo.png";
                case DatasetFileKind.MetallicExr: return "_metallic.exr";
                case DatasetFileKind.MetallicPng: return "_metallic.png";
                case DatasetFileKind.RoughnessExr: return "_roughness.exr";
                case DatasetFileKind.RoughnessPng: return "_roughness.png";
                case DatasetFileKind.SpecularExr: return "_specular.exr";
                case DatasetFileKind.SpecularPng: return "_specular.png";
                case DatasetFileKind.EmissionExr: return "_emission.exr";
                case DatasetFileKind.MaterialCoveragePng: return "_material_coverage.png";
                case DatasetFileKind.RelitPng:
                case DatasetFileKind.RelitHdrExr:
                    throw new ArgumentOutOfRangeException(nameof(kind), kind, "a relit file is named by its condition key: use RelitRelativePath");
                default: throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a dataset file kind");
            }
        }

        /// <summary>
        /// A relit view's suffix: <c>_light_sunset_090.png</c>, or <c>_light_sunset_090_hdr.exr</c> with <paramref name="hdr"/>
        /// (the key is a lighting condition's, <see cref="LightingKeys"/>).
        /// </summary>
        public static string RelitSuffix(string key, bool hdr) => "_light_" + key + (hdr ? "_hdr.exr" : ".png");

        /// <summary>The relit file's path relative to the dataset folder: <c>train/r_7_light_sunset_090.png</c>.</summary>
        public static string RelitRelativePath(DatasetSplit split, int index, string key, bool hdr) =>
            DatasetSplits.Name(split) + "/" + Stem(index) + RelitSuffix(key, hdr);

        /// <summary>The files every view of a split with these settings produces, colour first.</summary>
        public static IReadOnlyList<DatasetFileKind> FileKinds(SplitSettings split) => FileKinds(split, null);

        /// <summary>The files every view of a split produces, with the id maps when <paramref name="labels"/> are on (every split writes them).</summary>
        public static IReadOnlyList<DatasetFileKind> FileKinds(SplitSettings split, LabelSettings labels)
        {
            var kinds = new List<DatasetFileKind> { DatasetFileKind.Color };
            if (ExtraOutputs.HasPng(split.Depth)) kinds.Add(DatasetFileKind.DepthPng);
            if (ExtraOutputs.HasExr(split.Depth)) kinds.Add(DatasetFileKind.DepthExr);
            if (ExtraOutputs.HasPng(split.Normal)) kinds.Add(DatasetFileKind.NormalPng);
            if (ExtraOutputs.HasExr(split.Normal)) kinds.Add(DatasetFileKind.NormalExr);
            if (split.Mask) kinds.Add(DatasetFileKind.MaskPng);
            if (labels != null && labels.Enabled)
            {
                kinds.Add(DatasetFileKind.InstancePng);
                kinds.Add(DatasetFileKind.SemanticPng);
            }
            return kinds;
        }

        /// <summary>The files every view of <paramref name="split"/> produces: the split's own, the id maps with labels, the clean image of a split with exposure, the sharp image with motion blur.</summary>
        public static IReadOnlyList<DatasetFileKind> FileKinds(DatasetSettings settings, DatasetSplit split)
        {
            var kinds = (List<DatasetFileKind>)FileKinds(settings.Split(split), settings.Labels);
            if (ExposurePlan.Of(settings)?.WritesClean(split) == true) kinds.Add(DatasetFileKind.CleanColor);
            if (ShutterPlanning.IsOn(settings)) kinds.Add(DatasetFileKind.SharpPng);
            if (settings.Hdr != null && settings.Hdr.Applies(split)) kinds.Add(DatasetFileKind.HdrExr);
            MaterialPassFiles.AddKinds(settings.Materials, kinds);
            LightingKeys.AddFileKinds(settings, split, kinds);
            return kinds;
        }
    }
}
