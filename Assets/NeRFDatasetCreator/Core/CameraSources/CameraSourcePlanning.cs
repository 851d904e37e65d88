using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <see cref="CapturePlan"/> needs from the splits' camera sources: the imported cameras of each split, the
    /// problems that stop planning, the warnings that do not, and the file's intrinsics when a split asks for them.
    /// </summary>
    public static class CameraSourcePlanning
    {
        /// <summary>Whether any split places cameras with a formation (so the distance and its clip checks matter).</summary>
        public static bool AnyFormation(DatasetSettings settings) =>
            DatasetSplits.All.Any(s => settings.Split(s)?.Source == null || settings.Split(s).Source.IsFormation);

        /// <summary>
        /// A copy of <paramref name="settings"/> as the capture uses them: each imported split's count is its number of
        /// cameras, and the file's field of view and size replace the camera's where a split asks. The editor renders
        /// with these, and <see cref="CapturePlan"/> plans with them, so the written intrinsics are the rendered ones.
        /// </summary>
        public static DatasetSettings Resolved(DatasetSettings settings, out Dictionary<DatasetSplit, ImportedSplit> imported, List<ValidationProblem> problems = null)
        {
            problems = problems ?? new List<ValidationProblem>();
            var copy = settings.Clone();
            imported = Resolve(copy, problems);
            foreach (var pair in imported) copy.Split(pair.Key).Count = pair.Value.Cameras.Count;
            ApplyFileIntrinsics(copy, imported, problems);
            return copy;
        }

        /// <summary>Reads a transforms file, or the COLMAP text model in a folder.</summary>
        public static ImportedPoses Load(string path)
        {
            var full = System.IO.Path.GetFullPath(path);
            return Directory.Exists(full) ? ColmapModelReader.ReadFolder(full) : TransformsPoseReader.ReadFile(full);
        }

        /// <summary>The imported cameras of every split whose source is a file, or the problems that stop planning.</summary>
        public static Dictionary<DatasetSplit, ImportedSplit> Resolve(DatasetSettings settings, List<ValidationProblem> problems)
        {
            var result = new Dictionary<DatasetSplit, ImportedSplit>();
            foreach (var split in DatasetSplits.All)
            {
                var source = settings.Split(split)?.Source;
                var field = "splits." + DatasetSplits.Name(split) + ".source";
                if (source != null && source.IsVolume)
                {
                    var volume = VolumePlanning.Resolve(source, field, settings.Split(split).Count, VolumePlanning.Seed(settings.Seed, DatasetSplits.Name(split)), DatasetSplits.Name(split), problems);
                    if (volume != null) result[split] = volume;
                    continue;
                }
                if (source != null && source.IsFromScene)
                {
                    var fromScene = SceneCameraPlanning.Resolve(source, field, settings.Width, settings.Height, problems);
                    if (fromScene != null) result[split] = fromScene;
                    continue;
                }
                if (source == null || !source.IsImported || string.IsNullOrWhiteSpace(source.Path)) continue;
                ImportedPoses poses;
                try
                {
                    if (!File.Exists(source.Path) && !Directory.Exists(source.Path))
                    {
                        problems.Add(new ValidationProblem(field + ".path", source.Path, "is neither a file nor a folder (looked in " + Directory.GetCurrentDirectory() + ").",
                            "Give the path of a transforms JSON file or a COLMAP model folder, absolute or relative to the Unity project folder."));
                        continue;
                    }
                    poses = Load(source.Path);
                }
                catch (InvalidParameterException e)
                {
                    problems.AddRange(e.Problems.Select(p => Inner(field + ".path", p)));
                    continue;
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException || e is NotSupportedException)
                {
                    problems.Add(new ValidationProblem(field + ".path", source.Path, "cannot be read: " + e.Message, "Check the path and its permissions."));
                    continue;
                }
                var cameras = poses.OfSplit(source.FileSplit);
                if (cameras.Count == 0)
                {
                    problems.Add(new ValidationProblem(field + ".fileSplit", "\"" + source.FileSplit + "\"", "selects none of the " + poses.Cameras.Count + " cameras of " + source.Path + ".",
                        "Use \"\" for all of them, or the split the file gives its cameras (its file name transforms_<split>.json, nerfstudio's <split>_filenames, COLMAP names <split>_…)."));
                    continue;
                }
                if (cameras.Count > DatasetSettings.MaxViews)
                {
                    problems.Add(ValidationProblem.OutsideRange(field, cameras.Count, 1, DatasetSettings.MaxViews));
                    continue;
                }
                result[split] = new ImportedSplit(poses, cameras, field);
            }
            return result;
        }

        /// <summary>
        /// Sets the camera's field of view and the image size from the imported splits that ask for it; the problems
        /// when they disagree, give no image size, or clash with <c>camera.copyFromCamera</c>.
        /// </summary>
        public static void ApplyFileIntrinsics(DatasetSettings settings, Dictionary<DatasetSplit, ImportedSplit> imported, List<ValidationProblem> problems)
        {
            ImportedIntrinsics chosen = null;
            string chosenField = null;
            foreach (var pair in imported)
            {
                var source = settings.Split(pair.Key).Source;
                if (!source.UsesSourceIntrinsics) continue;
                var field = pair.Value.Field + (source.IsImported ? ".useFileIntrinsics" : ".useCameraIntrinsics");
                var what = source.IsImported ? "the file's cameras have" : "the scene's cameras have";
                var shared = ImportedPoses.SharedIntrinsics(pair.Value.Cameras);
                if (shared == null)
                    problems.Add(new ValidationProblem(field, "true", "needs one camera for the whole split, but " + what + " different intrinsics" +
                        (source.IsImported ? "." : " (" + SceneCameraPlanning.DescribeFovs(pair.Value.Cameras) + "); the Blender-format files hold one camera_angle_x per split."),
                        source.IsImported ? "Turn it off and set the camera by hand, or import a file with one camera." : "Give the cameras one field of view, or turn it off to render them all with the Camera step's."));
                else if (!string.IsNullOrWhiteSpace(settings.Camera.CopyFromCamera))
                    problems.Add(new ValidationProblem(field, "true", "and camera.copyFromCamera both set the field of view.", "Use one of them."));
                else if (chosen != null && !chosen.SameAs(shared))
                    problems.Add(new ValidationProblem(field, "true", "takes other intrinsics than " + chosenField + "; a dataset has one camera.", "Use the source's own intrinsics in one split only, or give the cameras one field of view."));
                else
                {
                    chosen = shared;
                    chosenField = field;
                }
            }
            if (chosen == null) return;
            if (chosen.HasSize && (chosen.Width < DatasetSettings.MinSize || chosen.Width > DatasetSettings.MaxSize || chosen.Height < DatasetSettings.MinSize || chosen.Height > DatasetSettings.MaxSize))
            {
                problems.Add(new ValidationProblem(chosenField, chosen.Width + "×" + chosen.Height, "is an image size outside " + DatasetSettings.MinSize + " to " + DatasetSettings.MaxSize + " pixels a side.",
                    "Turn it off and set a supported size by hand; the views keep their field of view."));
                return;
            }
            if (chosen.HasSize)
            {
                settings.Width = chosen.Width;
                settings.Height = chosen.Height;
            }
            settings.Camera.VerticalFovDegrees = chosen.VerticalFovDegrees(settings.Width, settings.Height);
        }

        /// <summary>A problem inside the file, shown under the source's path control: the file's own field goes into the value.</summary>
        static ValidationProblem Inner(string field, ValidationProblem p) =>
            new ValidationProblem(field, p.Field + (p.Value.Length > 0 ? " = " + p.Value : ""), p.Reason, p.Fix);

        /// <summary>Where the rendered views will differ from the file's (intrinsics the capture camera does not share).</summary>
        public static IEnumerable<ValidationProblem> Warnings(DatasetSettings settings, CameraIntrinsics intrinsics, Dictionary<DatasetSplit, ImportedSplit> imported)
        {
            foreach (var pair in imported)
            {
                if (pair.Value.Poses.Format == VolumePlanning.Format)
                {
                    // Rendered with the dataset's own camera: only the sampling's notes.
                    foreach (var w in pair.Value.Poses.Warnings) yield return w;
                    continue;
                }
                // A scene source's notes already name their own field; an imported file's are inside the file.
                foreach (var w in pair.Value.Poses.Warnings)
                    yield return pair.Value.Poses.Format == SceneCameraPlanning.Format ? w : Inner(pair.Value.Field + ".path", w);
                var k = ImportedPoses.SharedIntrinsics(pair.Value.Cameras);
                if (k == null)
                {
                    yield return new ValidationProblem(pair.Value.Field, pair.Value.Poses.Source, "has cameras with different intrinsics; every view is rendered with the dataset's one camera.",
                        "Compare only views with the dataset's intrinsics, or split the file.");
                    continue;
                }
                var angleX = k.CameraAngleX;
                var sizeDiffers = k.HasSize && (k.Width != intrinsics.Width || k.Height != intrinsics.Height);
                if (Math.Abs(angleX - intrinsics.CameraAngleX) > 1e-6 || sizeDiffers)
                    yield return new ValidationProblem(pair.Value.Field, pair.Value.Poses.Source,
                        "has camera_angle_x " + ValidationProblem.Format(angleX) + (k.HasSize ? " at " + k.Width + "×" + k.Height : "") + ", the dataset " +
                        ValidationProblem.Format(intrinsics.CameraAngleX) + " at " + intrinsics.Width + "×" + intrinsics.Height + ": same poses, other pictures.",
                        pair.Value.Poses.Format == SceneCameraPlanning.Format ? "Turn on useCameraIntrinsics to render with the cameras' own field of view." : "Turn on useFileIntrinsics to render the file's views exactly.");
                else if (k.HasSize && (Math.Abs(k.Cx - intrinsics.Cx) > 1e-6 || Math.Abs(k.Cy - intrinsics.Cy) > 1e-6 || Math.Abs(k.FlX - k.FlY) > 1e-6 * k.FlX))
                    yield return new ValidationProblem(pair.Value.Field, pair.Value.Poses.Source,
                        "has a principal point off the image centre or non-square pixels (cx " + ValidationProblem.Format(k.Cx) + ", cy " + ValidationProblem.Format(k.Cy) +
                        ", fl_x " + ValidationProblem.Format(k.FlX) + ", fl_y " + ValidationProblem.Format(k.FlY) + "), which the capture camera does not reproduce.",
                        "Compare against centred, square-pixel images.");
            }
        }
    }

    /// <summary>One split's imported cameras and the file they came from.</summary>
    public sealed class ImportedSplit
    {
        public ImportedSplit(ImportedPoses poses, IReadOnlyList<ImportedCamera> cameras, string field)
        {
            Poses = poses;
            Cameras = cameras;
            Field = field;
        }

        public ImportedPoses Poses { get; }
        public IReadOnlyList<ImportedCamera> Cameras { get; }

        /// <summary>The settings path of the source, e.g. <c>splits.test.source</c>.</summary>
        public string Field { get; }
    }
}
