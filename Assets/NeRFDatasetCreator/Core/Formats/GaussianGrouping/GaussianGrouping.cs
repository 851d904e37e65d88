using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The layout Gaussian Grouping trains on (lkeab/gaussian-grouping at 0ab60af), each rule from its loader
    /// (Documentation~/maintainers/labels-exports.md has the lines):
    /// <list type="bullet">
    /// <item>Only its COLMAP reader reads object masks: <c>Scene</c> picks it when <c>sparse/</c> exists
    /// (scene/__init__.py:43-44); the Blender reader builds <c>CameraInfo</c> without the <c>objects</c> field the tuple
    /// requires (scene/dataset_readers.py:34, 271-272) and stops. So the export is our COLMAP model plus masks.</item>
    /// <item>The mask of an image is <c>&lt;source&gt;/object_mask/&lt;image_name&gt;.png</c>, image_name being the image's
    /// file name up to its first dot (dataset_readers.py:95-98, 145; <c>--object_path</c> defaults to
    /// <c>object_mask</c>, arguments/__init__.py:57).</item>
    /// <item>It is read as <c>np.array(Image.open(path))</c> and used, unresized, as the class index of each pixel in a
    /// cross-entropy loss (utils/camera_utils.py:54; train.py:87-89): one 8-bit grey channel (DEVA's masks are
    /// <c>astype(np.uint8)</c>), values below <c>num_classes</c>, at the image's own size — so the trainer must load the
    /// images at full size (<c>-r 1</c>).</item>
    /// <item><c>num_classes</c> comes from the <c>--config_file</c> JSON (train.py:235, default 200); the shipped config
    /// and render.py use 256 (config/gaussian_dataset/train.json, script/train.sh).</item>
    /// <item><c>--train_split</c> trains on the images named in <c>images_train/</c> and tests on the rest
    /// (dataset_readers.py:149-160, names up to the first dot).</item>
    /// </list>
    /// </summary>
    public static class GaussianGrouping
    {
        public const string FolderName = "gaussian_grouping";
        public const string ObjectMaskFolder = "object_mask";
        public const string TrainSplitFolder = "images_train";

        /// <summary>The <c>--config_file</c> this export writes (<c>{"num_classes": 256}</c>).</summary>
        public const string ConfigFileName = "gaussian_grouping_config.json";

        /// <summary>Which mask value is which object of the dataset (the masks hold indices, not the dataset's instance ids).</summary>
        public const string ObjectIndexFileName = "object_ids.json";

        /// <summary>The classifier's outputs, as in the shipped config and render.py's script: every mask value must be below it.</summary>
        public const int NumClasses = 256;

        /// <summary>Objects an 8-bit mask can name besides the background (value 0).</summary>
        public const int MaxObjects = 255;

        /// <summary>
        /// <c>image_name</c> of the loader: <c>os.path.basename(image_path).split(".")[0]</c> (dataset_readers.py:95-96),
        /// e.g. <c>train_r_0.png</c> → <c>train_r_0</c>.
        /// </summary>
        public static string ImageName(string colmapImageName)
        {
            var file = Path.GetFileName(colmapImageName.Replace('\\', '/'));
            var dot = file.IndexOf('.');
            return dot < 0 ? file : file.Substring(0, dot);
        }

        /// <summary>The mask file of an image, relative to the export: <c>object_mask/&lt;image_name&gt;.png</c> (dataset_readers.py:98).</summary>
        public static string MaskPath(string colmapImageName) => ObjectMaskFolder + "/" + ImageName(colmapImageName) + ".png";

        /// <summary>
        /// The mask value of each dataset instance id: 1, 2, 3… in the order of <paramref name="instanceIds"/> (ascending),
        /// 0 for the background. Throws when more than <see cref="MaxObjects"/> ids are given.
        /// </summary>
        public static Dictionary<int, byte> MaskValues(IReadOnlyList<int> instanceIds)
        {
            if (instanceIds.Count > MaxObjects)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("--to gaussian-grouping", instanceIds.Count + " objects",
                        "is more than the " + MaxObjects + " objects an 8-bit Gaussian Grouping mask can name (its loader reads the mask as 8-bit class indices).",
                        "Capture with coarser instances (labels.instances \"prefab\" or \"child\"), or a smaller part of the scene."),
                });
            var values = new Dictionary<int, byte>();
            var sorted = new List<int>(instanceIds);
            sorted.Sort();
            for (var i = 0; i < sorted.Count; i++) values[sorted[i]] = (byte)(i + 1);
            return values;
        }

        /// <summary>The 8-bit mask of one view from its 16-bit instance map (same size, same row order); ids absent from <paramref name="values"/> become 0.</summary>
        public static byte[] Mask(ushort[] instanceMap, IReadOnlyDictionary<int, byte> values)
        {
            var lookup = new byte[65536];
            foreach (var pair in values) lookup[pair.Key] = pair.Value;
            var mask = new byte[instanceMap.Length];
            for (var i = 0; i < mask.Length; i++) mask[i] = lookup[instanceMap[i]];
            return mask;
        }
    }
}
