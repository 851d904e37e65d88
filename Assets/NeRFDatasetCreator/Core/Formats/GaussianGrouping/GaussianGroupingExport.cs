using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset convert d --to gaussian-grouping</c>: the COLMAP model Gaussian Grouping's COLMAP reader loads
    /// (<see cref="DatasetConverter"/>'s COLMAP export: <c>images/</c>, <c>sparse/0/</c>) plus, from the dataset's labels,
    /// <c>object_mask/&lt;image_name&gt;.png</c> per image (8-bit, 0 = background, 1…N = the objects),
    /// <c>object_ids.json</c> (which value is which labelled object), the <c>--config_file</c> with <c>num_classes</c>,
    /// and <c>images_train/</c> (copies of the train images) for <c>--train_split</c> when the dataset has val or test
    /// views. The rules and their source lines are in <see cref="GaussianGrouping"/>.
    /// </summary>
    public static class GaussianGroupingExport
    {
        public const string What = "--to gaussian-grouping";

        /// <param name="labelled">The dataset's labels, loaded (<see cref="LabelledDataset.Load"/>) before anything is written.</param>
        public static ConversionResult Write(ExportScene scene, LabelledDataset labelled, string outDir, IReadOnlyList<CloudPoint> points, List<ValidationProblem> warnings,
            ColmapOptions colmap, StagedOutput staged)
        {
            outDir = Path.GetFullPath(outDir);
            var names = ColmapTextWriter.ImageNames(scene.Frames);
            var masks = names.Select(n => Path.Combine(outDir, GaussianGrouping.MaskPath(n))).ToList();
            // The loader keeps a name up to its first dot: two images that agree up to there would share one mask.
            var clash = names.GroupBy(GaussianGrouping.ImageName).FirstOrDefault(g => g.Count() > 1);
            if (clash != null)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("file_path", string.Join(", ", clash), "are one image name to Gaussian Grouping, which cuts names at the first dot (" + clash.Key + ").",
                        "Give the images names without dots before the extension."),
                });
            var values = GaussianGrouping.MaskValues(ObjectsToName(scene, labelled));
            var config = Path.Combine(outDir, GaussianGrouping.ConfigFileName);
            var ids = Path.Combine(outDir, GaussianGrouping.ObjectIndexFileName);
            var trainSplit = scene.Frames.Any(f => f.Split != "train");
            var trainCopies = trainSplit
                ? scene.Frames.Select((f, i) => (frame: f, name: names[i])).Where(p => p.frame.Split == "train")
                    .Select(p => (from: Path.Combine(scene.RootDirectory, p.frame.ImagePath), to: Path.Combine(outDir, GaussianGrouping.TrainSplitFolder, p.name))).ToList()
                : new List<(string from, string to)>();
            foreach (var path in masks.Concat(new[] { config, ids }).Concat(trainCopies.Select(c => c.to))) DatasetConverter.EnsureAbsent(path);

            var colmapResult = DatasetConverter.ToColmap(scene, outDir, points, warnings, false, colmap ?? ColmapOptions.Default, staged);
            // The COLMAP export's note that COLMAP has no splits does not hold here: --train_split reads images_train/.
            if (trainSplit) warnings.RemoveAll(w => w.Reason.StartsWith("COLMAP has no splits", System.StringComparison.Ordinal));

            var written = new List<string>(colmapResult.WrittenFiles);
            var absent = 0;
            for (var i = 0; i < scene.Frames.Count; i++)
            {
                var mask = GaussianGrouping.Mask(labelled.ReadInstanceMap(scene, i), values);
                if (mask.All(v => v == 0)) absent++;
                staged.WriteNewBytes(masks[i], PngWriter.Encode(mask, scene.Intrinsics.Width, scene.Intrinsics.Height, PngPixelFormat.Gray8));
                written.Add(masks[i]);
            }
            if (absent > 0)
                warnings.Add(new ValidationProblem(GaussianGrouping.ObjectMaskFolder, absent + " of " + scene.Frames.Count + " masks",
                    "show no labelled object (background only).", "Nothing to do if those views look away from the labelled objects."));
            staged.WriteNewText(config, new JObject { ["num_classes"] = GaussianGrouping.NumClasses }.ToString() + "\n");
            staged.WriteNewText(ids, ObjectIds(labelled.Table, values));
            written.Add(config);
            written.Add(ids);
            foreach (var (from, to) in trainCopies)
            {
                staged.Copy(from, to);
                written.Add(to);
            }
            return new ConversionResult(outDir, outDir, written, warnings, Commands(outDir, trainSplit));
        }

        /// <summary>
        /// The instance ids the masks name: every object of labels.json when they fit in 8 bits, else only those some
        /// instance map shows (ids of objects no view sees are not worth a value).
        /// </summary>
        static IReadOnlyList<int> ObjectsToName(ExportScene scene, LabelledDataset labelled)
        {
            var all = labelled.Table.Instances.Select(i => i.Id).ToList();
            if (all.Count <= GaussianGrouping.MaxObjects) return all;
            var seen = new bool[65536];
            for (var i = 0; i < scene.Frames.Count; i++)
                foreach (var id in labelled.ReadInstanceMap(scene, i)) seen[id] = true;
            return all.Where(id => id < seen.Length && seen[id]).ToList(); // an id beyond 16 bits is in no map
        }

        static string ObjectIds(LabelTable table, IReadOnlyDictionary<int, byte> values)
        {
            var objects = new JArray();
            foreach (var pair in values.OrderBy(p => p.Value))
            {
                var label = table.Instance(pair.Key);
                objects.Add(new JObject
                {
                    ["value"] = pair.Value,
                    ["instance_id"] = pair.Key,
                    ["name"] = label?.Name ?? "",
                    ["path"] = label?.Path ?? "",
                    ["class"] = label?.ClassName ?? "",
                });
            }
            return new JObject
            {
                ["about"] = "object_mask/*.png hold these values (0 = background); Gaussian Grouping's select_obj_id is the value. instance_id is the object's id in the dataset's labels.json and instance maps.",
                ["background"] = 0,
                ["objects"] = objects,
            }.ToString() + "\n";
        }

        /// <summary>Training at full size (-r 1: the masks are not resized with the images) with the written num_classes, then its segmentation render.</summary>
        public static IReadOnlyList<string> Commands(string outDir, bool trainSplit)
        {
            // Named after the dataset for the default <dataset>/gaussian_grouping, after the folder itself for --out (issue 33).
            var model = "output/" + ExportPaths.RunName(outDir, GaussianGrouping.FolderName);
            return new[]
            {
                "python train.py -s " + Quote(outDir) + " -r 1 -m " + Quote(model) + " --config_file " + Quote(Path.Combine(outDir, GaussianGrouping.ConfigFileName)) +
                    (trainSplit ? " --eval --train_split" : "") + "   (Gaussian Grouping)",
                "python render.py -m " + Quote(model) + " --num_classes " + GaussianGrouping.NumClasses.ToString(CultureInfo.InvariantCulture),
            };
        }

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;
    }
}
