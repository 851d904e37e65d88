using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A deliberately small reader of a Blender-format dataset (nerf_synthetic or this plugin's output) for the
    /// converters: <c>transforms_{train,val,test}.json</c> (train required), <c>file_path</c> resolved like the
    /// loaders do (<c>+ ".png"</c> when extensionless), W×H from each PNG's IHDR, <c>camera_angle_x</c> → a square-pixel
    /// pinhole, optional <c>cx</c>/<c>cy</c>, all as <see cref="DatasetFolder"/> reads them (lenient). Picks up the extras
    /// the frames' keys name, from the key only: <c>depth_path</c> (16-bit grey), <c>mask_path</c> (8-bit grey), <c>points3d.ply</c>
    /// when dataset_config.json records it (<see cref="PointCloudOwnership"/>; any other is a warning),
    /// <c>scene_normalisation</c>; train's <c>aabb_scale</c> and the target's reach from <c>dataset_config.json</c>
    /// (<see cref="DatasetTargetReach"/>) for instant-ngp's cube; the lens distortion (<see cref="TransformsLens"/>).
    /// </summary>
    public static class BlenderDatasetLoader
    {
        public const string PointCloudFileName = PointCloudOwnership.FileName;

        public static ExportScene Load(string datasetDirectory, ICollection<ValidationProblem> warnings = null)
        {
            warnings = warnings ?? new List<ValidationProblem>();
            var problems = new List<ValidationProblem>();
            if (string.IsNullOrEmpty(datasetDirectory) || !Directory.Exists(datasetDirectory))
                Throw(new ValidationProblem("datasetDir", datasetDirectory ?? "", "is not an existing folder.", "Pass the folder that contains transforms_train.json."));
            var root = Path.GetFullPath(datasetDirectory);
            if (!File.Exists(Path.Combine(root, "transforms_train.json")))
                Throw(new ValidationProblem("datasetDir", root, "has no transforms_train.json, so it is not a Blender-format (nerf_synthetic) dataset.", "Pass the folder that contains transforms_{train,val,test}.json."));

            var frames = new List<ExportFrame>();
            var images = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
            var declaredSizes = new List<(string split, string w, string h, double? wValue, double? hValue)>();
            double? angleX = null;
            double? cx = null, cy = null;
            SceneNormalisation normalisation = null;
            int? aabbScale = null;
            PngInfo size = null;
            string sizeSource = null;
            LensDistortion lens = null;
            string lensSource = null;
            foreach (var split in DatasetSplits.Names)
            {
                var jsonPath = Path.Combine(root, DatasetLayout.TransformsFileName(split));
                if (!File.Exists(jsonPath))
                {
                    warnings.Add(new ValidationProblem(DatasetLayout.TransformsFileName(split), jsonPath, "is missing; the export has no " + split + " frames.", "bmild/nerf and nerf-pytorch need all three split files."));
                    continue;
                }
                DatasetSplitFile json;
                try { json = DatasetFolder.ReadSplit(root, split, DatasetReadMode.Lenient); }
                catch (SettingsFormatException e) { Throw(new ValidationProblem(Path.GetFileName(jsonPath), jsonPath, "is not valid JSON: line " + e.Line + ", column " + e.Column + ": " + e.Detail, "Fix or regenerate the file.")); return null; }
                catch (FileTooLargeException e) { Throw(new ValidationProblem(Path.GetFileName(jsonPath), jsonPath, e.Reason, "Pass a dataset whose split files were written by Blender, this plugin or another NeRF tool.")); return null; }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException) { Throw(new ValidationProblem(Path.GetFileName(jsonPath), jsonPath, "cannot be read: " + e.Message, "Check the file's permissions.")); return null; }

                if (!(json.CameraAngleX is double angleValue) || !(angleValue > 0 && angleValue < Math.PI))
                    problems.Add(new ValidationProblem(split + ".camera_angle_x", json.Value("camera_angle_x")?.ToString() ?? "missing", "must be the horizontal field of view in radians, in (0, π).", "Write camera_angle_x, e.g. 0.6911112070083618 for nerf_synthetic."));
                else if (angleX == null) angleX = angleValue;
                else if (Math.Abs(angleX.Value - angleValue) > 1e-9)
                    warnings.Add(new ValidationProblem(split + ".camera_angle_x", angleValue.ToString("R", CultureInfo.InvariantCulture), "differs from train's " + angleX.Value.ToString("R", CultureInfo.InvariantCulture) + "; the export uses train's (NeRF itself uses the test file's).", "Write the same field of view in every split."));
                if (cx == null && json.Has("cx") && json.Has("cy"))
                {
                    if (json.Intrinsics.Cx is double cxValue && json.Intrinsics.Cy is double cyValue) { cx = cxValue; cy = cyValue; }
                    else problems.Add(new ValidationProblem(split + ".cx, cy", json.Text("cx") + ", " + json.Text("cy"),
                        "must be the principal point in pixels, two numbers.", "Write cx and cy as numbers (W/2 and H/2 without lens shift), or remove both."));
                }
                if (json.Has("w") || json.Has("h")) declaredSizes.Add((split, json.Text("w"), json.Text("h"), json.Intrinsics.W, json.Intrinsics.H));
                if (normalisation == null && json.Has("scene_normalisation")) normalisation = SceneNormalisation.FromJson(json.Value("scene_normalisation"));
                if (split == "train") aabbScale = AabbScale.Declared(json.Value("aabb_scale"), Path.GetFileName(jsonPath), warnings);
                // The lens (k1…k4, p1, p2, camera_model / is_fisheye): one for the whole dataset, carried by every export.
                // A split without frames has no images, so its lens (or none) cannot contradict the others.
                if (json.HasFrameList && json.FrameCount > 0)
                {
                    problems.AddRange(json.LensProblems);
                    var splitLens = json.Lens;
                    if (lensSource == null) { lens = splitLens; lensSource = Path.GetFileName(jsonPath); }
                    else if (!TransformsLens.Same(lens, splitLens))
                        problems.Add(new ValidationProblem(Path.GetFileName(jsonPath), TransformsLens.Describe(splitLens),
                            "has another lens than " + lensSource + " (" + TransformsLens.Describe(lens) + "); convert writes one shared camera for the whole dataset.",
                            "Write the same camera_model and k1…k4, p1, p2 in every split file."));
                }

                if (!json.HasFrameList)
                {
                    problems.Add(new ValidationProblem(Path.GetFileName(jsonPath) + ": frames", json.FramesShown,
                        "must be a list of frames (empty for an unused split).", "Regenerate the split file."));
                    continue;
                }
                if (json.FrameCount == 0)
                {
                    // Only train is needed (validate agrees): an unused val or test split converts without frames.
                    if (split == "train")
                        problems.Add(new ValidationProblem(Path.GetFileName(jsonPath) + ": frames", "[]",
                            "is empty; every loader trains on the train split, so there is nothing to convert.", "Capture at least one train view."));
                    else
                        warnings.Add(new ValidationProblem(Path.GetFileName(jsonPath) + ": frames", "[]", "is empty; the export has no " + split + " frames.",
                            "Nothing to do if the split is unused on purpose (bmild/nerf and nerf-pytorch need " + split + " views)."));
                    continue;
                }
                foreach (var frame in json.Frames)
                {
                    var field = split + ".frames[" + frame.Index + "]";
                    var filePath = frame.FilePath;
                    if (filePath == null) { problems.Add(new ValidationProblem(field + ".file_path", "missing", "must be the image path.", "Write file_path, e.g. ./train/r_0.")); continue; }
                    var imageFile = frame.Image;
                    if (!imageFile.IsInside) { problems.Add(new ValidationProblem(field + ".file_path", filePath, imageFile.Outside + "; convert never reads outside the dataset.", "Copy the images into the dataset folder and name them relative to it.")); continue; }
                    if (!imageFile.Exists) { problems.Add(new ValidationProblem(field + ".file_path", filePath, "names no image (looked for the path and the path + \".png\").", "Copy the images next to the split files.")); continue; }
                    var image = imageFile.Relative;
                    if (!images.Add(image)) { problems.Add(new ValidationProblem(field + ".file_path", filePath, "names " + image + ", which another frame already uses; the export would hold it twice.", "Give every frame its own image.")); continue; }
                    if (!TryMatrix(frame.TransformMatrix, out var c2w, out var reason)) { problems.Add(new ValidationProblem(field + ".transform_matrix", frame.Text("transform_matrix") ?? "missing", reason, "Write a 4×4 rigid camera-to-world matrix.")); continue; }

                    var header = ReadPng(root, image);
                    if (size == null) { size = header; sizeSource = image; }
                    else if (header.Width != size.Width || header.Height != size.Height)
                        problems.Add(new ValidationProblem(field + ".file_path", image, $"is {header.Width}×{header.Height} but {sizeSource} is {size.Width}×{size.Height}.", "Every loader needs one image size for the whole dataset."));
                    // Keys only: the files the frame names (depth_path, else nerfstudio's depth_file_path; mask_path), never
                    // a file guessed from the image's name (nerf_synthetic's own r_0_depth_0000.png are 8-bit pictures).
                    var depth = Extra(frame.Named("depth_path") ?? frame.Named("depth_file_path"), image, 16, size, "depth", out var unusableDepth);
                    var mask = Extra(frame.Named("mask_path"), image, 8, size, "mask", out var unusableMask);
                    // Every unusable companion is named: left out here, refused by colmap --depths (GaussianSplattingDepths.Check).
                    if (unusableDepth != null) warnings.Add(LeftOut(unusableDepth));
                    if (unusableMask != null) warnings.Add(LeftOut(unusableMask));
                    var instance = frame.Named(LabelFrameKeys.Instance);
                    var exportFrame = new ExportFrame(split, image, c2w, depth, mask, frame.Time.Time, unusableDepth)
                    {
                        Timing = frame.Time,
                        InstancePath = instance != null && instance.IsInside ? instance.Relative : null,
                    };
                    MotionBlurExports.Read(frame.Shutter, exportFrame);
                    frames.Add(exportFrame);
                }
            }
            InvalidParameterException.ThrowIfAny(problems.ToArray());
            if (angleX == null || size == null) Throw(new ValidationProblem("datasetDir", root, "has no usable frame.", "Regenerate the dataset."));

            foreach (var (split, w, h, wValue, hValue) in declaredSizes)
                if (!(wValue == size.Width && hValue == size.Height))
                    warnings.Add(new ValidationProblem(split + ".w, h", (w ?? "?") + " × " + (h ?? "?"),
                        "differ from the images' " + size.Width + " × " + size.Height + "; convert uses the images' size and ignores w and h.", "Write the images' size as w and h (validate reports it too)."));
            ReportPartial(frames, f => f.DepthPath, "depth", warnings);
            ReportPartial(frames, f => f.MaskPath, "mask", warnings);
            var focal = 0.5 * size.Width / Math.Tan(0.5 * angleX.Value);
            var vfov = 2 * Math.Atan(0.5 * size.Height / focal) * 180 / Math.PI;
            var shiftX = cx == null ? 0 : (size.Width / 2.0 - cx.Value) / size.Width;
            var shiftY = cy == null ? 0 : (cy.Value - size.Height / 2.0) / size.Height;
            var intrinsics = CameraIntrinsics.FromVerticalFov(vfov, size.Width, size.Height, shiftX, shiftY);
            // Only the cloud this plugin recorded is the target's surface; 3DGS writes its random cube under the same name.
            // A link is never followed out of the dataset.
            var plyPath = Path.Combine(root, PointCloudFileName);
            var isLink = File.Exists(plyPath) && PathSafety.IsLink(plyPath);
            // dataset_config.json, read once: the cloud's record, the target's reach (a broken config is a warning there) and
            // whether the capture was inside-out (false when the config does not say or cannot be read).
            var config = DatasetConfig.Read(root);
            var ply = !isLink && PointCloudOwnership.IsOwn(root, config, warnings) ? PointCloudFileName : null;
            return new ExportScene(root, intrinsics, frames, ply, normalisation,
                declaredAabbScale: aabbScale, targetReach: DatasetTargetReach.Read(config, warnings), insideOut: config.Config?.InsideOut == true, lens: lens,
                unityFrame: config.Config?.Json[UnityFrameRecord.Key] as Newtonsoft.Json.Linq.JObject);
        }

        /// <summary>The PNG header of a dataset image; a file that is not a whole PNG is a problem naming it.</summary>
        static PngInfo ReadPng(string root, string relativePath)
        {
            try
            {
                return PngInfo.Read(Path.Combine(root, relativePath));
            }
            catch (InvalidDataException e)
            {
                Throw(new ValidationProblem("file_path", relativePath, e.Message, "Regenerate or replace the image."));
                return null;
            }
        }

        /// <summary>
        /// A companion image (depth, mask) the frame's key names, if it exists inside the dataset with the expected format;
        /// a file that is named but cannot be used — another bit depth, another size, a header claiming some other size,
        /// truncated, unreadable, outside the dataset or through a link — is null with <paramref name="unusable"/> naming it
        /// and saying why (one rule for all of them). A named file that does not exist is left out silently (validate reports it).
        /// </summary>
        static string Extra(DatasetFile file, string image, int bitDepth, PngInfo size, string what, out ValidationProblem unusable)
        {
            unusable = null;
            if (file == null) return null;
            var candidate = file.Relative;
            string why = null;
            if (!file.IsInside) why = file.Outside; // outside the dataset or through a link: never read
            else if (!file.Exists) return null;
            else
            {
                try
                {
                    var h = PngInfo.Read(file.FullPath);
                    if (h.ColorType != PngInfo.ColorTypeGray || h.BitDepth != bitDepth)
                        why = "is " + h.Describe() + ", not " + bitDepth + "-bit grey";
                    else if (h.Width != size.Width || h.Height != size.Height)
                        why = "is " + h.Width + "×" + h.Height + ", not the images' " + size.Width + "×" + size.Height;
                }
                catch (InvalidDataException e) { why = e.Message.TrimEnd('.'); }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException) { why = "cannot be read (" + e.Message.TrimEnd('.') + ")"; }
            }
            if (why == null) return candidate;
            unusable = new ValidationProblem(what, candidate, why + (file.IsInside ? ", not this plugin's " + what + " layout (Documentation~/output-format.md)" : ""),
                "Re-capture the " + what + " with this plugin, or delete the file to export " + image + " without " + what + ".");
            return null;
        }

        static ValidationProblem LeftOut(ValidationProblem unusable) =>
            new ValidationProblem(unusable.Field, unusable.Value, unusable.Reason + "; it is left out of the export" +
                (unusable.Field == "depth" ? " (convert --to colmap --depths refuses it)." : "."), unusable.Fix);

        static void ReportPartial(List<ExportFrame> frames, Func<ExportFrame, string> path, string what, ICollection<ValidationProblem> warnings)
        {
            var with = frames.Count(f => path(f) != null);
            if (with > 0 && with < frames.Count)
                warnings.Add(new ValidationProblem(what, with + " of " + frames.Count + " frames",
                    $"only some frames have a usable {what} image; nerfstudio needs it on all frames or none, so its export leaves {what} out (instant-ngp reads train's only; colmap --depths marks images without depth unreliable).",
                    $"Re-capture with {what} for every split."));
        }

        static bool TryMatrix(Matrix4x4d? written, out Matrix4x4d matrix, out string reason)
        {
            matrix = written ?? Matrix4x4d.Identity;
            reason = "must be a 4×4 array of numbers.";
            if (!written.HasValue) return false;
            var pose = DatasetValidator.PoseProblems(matrix);
            if (pose.Count > 0)
            {
                reason = string.Join(" ", pose);
                return false;
            }
            return true;
        }

        static void Throw(ValidationProblem problem) => throw new InvalidParameterException(new[] { problem });
    }
}
