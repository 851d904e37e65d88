using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the label exports read of a dataset: its <c>labels.json</c> and, per frame, the instance map its
    /// <c>instance_path</c> names (<c>r_&lt;i&gt;_instance_0000.png</c>, 16-bit grey, 0 = background). A dataset without labels, or a frame
    /// without its map, is refused before anything is written, naming the file and the fix.
    /// </summary>
    public sealed class LabelledDataset
    {
        LabelledDataset(LabelTable table, IReadOnlyList<string> instanceMaps)
        {
            Table = table;
            InstanceMaps = instanceMaps;
        }

        public LabelTable Table { get; }

        /// <summary>Per frame of the scene, in its order: the instance map's path relative to the dataset root.</summary>
        public IReadOnlyList<string> InstanceMaps { get; }

        /// <param name="what">The export asking, for the messages (e.g. "--to gaussian-grouping").</param>
        public static LabelledDataset Load(ExportScene scene, string what)
        {
            var labels = Path.Combine(scene.RootDirectory, DatasetLayout.LabelsFileName);
            if (!File.Exists(labels))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(what, scene.RootDirectory,
                        "needs the dataset's object labels, but it has no " + DatasetLayout.LabelsFileName + " (it was captured without labels).",
                        "Capture it again with labels on (the window's Labels section, or " + LabelSettingsJson.TurnOn + " in the settings)."),
                });
            var table = LabelsJson.ReadFile(labels);
            var maps = new List<string>();
            var problems = new List<ValidationProblem>();
            foreach (var frame in scene.Frames)
            {
                // Keys only: the map the frame's instance_path names (DatasetFolder), never one guessed from the image's name.
                var map = frame.InstancePath;
                maps.Add(map);
                if (map == null)
                    problems.Add(new ValidationProblem(what, frame.ImagePath, "names no instance map inside the dataset (" + LabelFrameKeys.Instance + "): every frame needs one, and files are never guessed from the image's name.",
                        "Capture the dataset again with labels on for every split (this plugin writes " + LabelFrameKeys.Instance + " with each map)."));
                else if (!File.Exists(Path.Combine(scene.RootDirectory, map)))
                    problems.Add(new ValidationProblem(what, map, "is missing: every frame needs its instance map beside its image.",
                        "Restore it from the capture, or capture the dataset again with labels on for every split."));
            }
            InvalidParameterException.ThrowIfAny(problems.ToArray());
            return new LabelledDataset(table, maps);
        }

        /// <summary><c>train/r_0.png</c> → <c>train/r_0_instance_0000.png</c>.</summary>
        public static string InstanceMapOf(string imagePath)
        {
            var normalised = ExportPaths.Normalise(imagePath);
            var dot = normalised.LastIndexOf('.');
            var slash = normalised.LastIndexOf('/');
            var stem = dot > slash ? normalised.Substring(0, dot) : normalised;
            return stem + DatasetLayout.Suffix(DatasetFileKind.InstancePng);
        }

        /// <summary>Frame <paramref name="index"/>'s instance map, rows top first; refused when its size is not the images'.</summary>
        public ushort[] ReadInstanceMap(ExportScene scene, int index)
        {
            var path = Path.Combine(scene.RootDirectory, InstanceMaps[index]);
            var map = PngGray16Reader.Read(path, out var width, out var height, "instance map");
            if (width != scene.Intrinsics.Width || height != scene.Intrinsics.Height)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(InstanceMaps[index], width + "×" + height, "is not the images' size " + scene.Intrinsics.Width + "×" + scene.Intrinsics.Height + ".",
                        "Restore the instance maps from the capture."),
                });
            // An id labels.json does not know would silently become background in every export's masks.
            var unknown = new SortedSet<int>();
            foreach (var id in map)
                if (id != 0 && Table.Instance(id) == null && unknown.Add(id) && unknown.Count > 10) break;
            if (unknown.Count > 0)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(InstanceMaps[index], "ids " + string.Join(", ", unknown.Take(10)) + (unknown.Count > 10 ? " …" : ""),
                        "holds instance ids that " + DatasetLayout.LabelsFileName + " does not list, so no export could name their objects.",
                        "Restore " + DatasetLayout.LabelsFileName + " and the instance maps from the same capture."),
                });
            return map;
        }
    }
}
