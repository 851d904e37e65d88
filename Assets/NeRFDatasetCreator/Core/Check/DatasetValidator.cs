using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Checks a Blender-format dataset folder (ours or nerf_synthetic's) against what the loaders need, reading it
    /// through <see cref="DatasetFolder"/> (strict, streamed): the three transforms files parse; <c>camera_angle_x</c> is in (0, π) and the same in every split; every referenced
    /// image exists, is a complete PNG, and all share one size and channel layout (read from the PNG header);
    /// every matrix is finite, has last row 0 0 0 1 and an orthonormal rotation with |det − 1| &lt; 1e-4; extra
    /// files named by per-frame keys exist inside the folder (<see cref="DatasetFile"/>) with the documented format; a <c>points3d.ply</c> that dataset_config.json
    /// does not record is a warning (<see cref="PointCloudOwnership"/>). Every problem is listed, one per line.
    /// </summary>
    public static class DatasetValidator
    {
        public const double RotationTolerance = 1e-4;

        public static DatasetValidationReport Validate(string folder)
        {
            var report = new DatasetValidationReport { Folder = folder };
            // A file, a missing folder, a capture's working folder or an export: one problem saying which (issue 33).
            var notADataset = NotADatasetFolder.Describe(folder);
            if (notADataset != null || !Directory.Exists(folder))
            {
                report.Problems.Add(DatasetProblem.Structure(folder, -1, null, notADataset ?? "the dataset folder does not exist."));
                return report;
            }
            // Read once; the checks below take it (a malformed config is not validate's concern, an unreadable one is).
            var config = DatasetConfig.Read(folder);
            if (config.State == DatasetConfigState.Unreadable)
                report.Problems.Add(DatasetProblem.Structure(DatasetLayout.ConfigFileName, -1, null, "cannot be read: " + config.Error + " (check the file's permissions)."));
            // eval_protocol.json: evaluate and every export read it, so a damaged one is a problem here (issue 35).
            try { EvalProtocolFile.Read(folder); }
            catch (InvalidParameterException e)
            {
                foreach (var p in e.Problems) report.Problems.Add(DatasetProblem.Structure(EvalProtocolFile.FileName, -1, null, p.Field + " " + p.Reason + " " + p.Fix));
            }
            var state = new ImageState { SkipFiles = config.IsPlanOnly };
            if (state.SkipFiles)
                report.Warnings.Add(DatasetProblem.Structure(DatasetLayout.ConfigFileName, -1, null,
                    "says the images were not rendered (a plan from `nerf-dataset plan`): image and extra-file checks are skipped."));
            double? firstAngle = null;
            string firstAngleFile = null;
            // The object's size is not in a Blender-format dataset, so the check is for its centre at the origin
            // (where the loaders assume it): a camera nearer than NeRF's near 2 or beyond its far 6 cannot see it.
            var cameraCentres = new LoaderRangeCheck.Tally(0);
            var timeRecord = config.Config?.Time != null;
            var timeFramesBySplit = new Dictionary<DatasetSplit, IReadOnlyList<TimeDatasetChecks.Kept>>();
            var labelMaps = false;
            foreach (var split in DatasetSplits.All)
            {
                var file = DatasetLayout.TransformsFileName(split);
                var path = Path.Combine(folder, file);
                if (!File.Exists(path))
                {
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null,
                        "is missing; bmild/nerf and nerf-pytorch open all three transforms files (write an empty \"frames\" list for an unused split)."));
                    continue;
                }
                // Streamed frame by frame (a 300 000-view plan's files are 87 MB each). What the frames add is undone if
                // the file turns out to be malformed further on, so a broken file reports its parse error alone, as before.
                var checkpoint = new Checkpoint(report, state, cameraCentres, split);
                var needsDepthScale = false;
                var timeFrames = new KeptTimeFrames();
                var keepEveryTimeFrame = timeRecord;
                DatasetSplitFile doc;
                try
                {
                    doc = DatasetFolder.ReadSplit(folder, DatasetSplits.Name(split), DatasetReadMode.Strict, frame =>
                    {
                        if (frame.FilePath != null)
                        {
                            var key = ExportPaths.Normalise(frame.FilePath);
                            if (!state.FilePaths.Add(key, file, frame.Index, out var first))
                                report.Problems.Add(DatasetProblem.Structure(file, frame.Index, frame.FilePath,
                                    "file_path is also " + first.file + " frame " + first.index + "'s; two frames of one image train on it twice and exports write it twice (give every frame its own image)."));
                        }
                        if (frame.TransformMatrix.HasValue && frame.TransformMatrix.Value.IsFinite) cameraCentres.Add(frame.TransformMatrix.Value.Translation);
                        CheckFrame(folder, file, frame, state, report);
                        if (frame.FileKey("depth_path") != null) needsDepthScale = true;
                        if (frame.FileKey(LabelFrameKeys.Instance) != null || frame.FileKey(LabelFrameKeys.Semantic) != null) labelMaps = true;
                        timeFrames.Add(TimeDatasetChecks.Keep(frame, keepEveryTimeFrame));
                    });
                }
                catch (SettingsFormatException e)
                {
                    cameraCentres = checkpoint.Restore();
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null, "line " + e.Line + ", column " + e.Column + ": " + e.Detail));
                    continue;
                }
                catch (FileTooLargeException e)
                {
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null, e.Reason));
                    continue;
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    cameraCentres = checkpoint.Restore();
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null, "cannot be read: " + e.Message + " (check the file's permissions)."));
                    continue;
                }
                state.Referenced.UnionWith(checkpoint.Referenced);
                timeFramesBySplit[split] = timeFrames;
                var frameCount = doc.FrameCount;
                // The document's own problems come before its frames', as the file reads.
                report.Problems.InsertRange(checkpoint.ProblemCount, doc.Problems.Select(p => DatasetProblem.Structure(file, -1, null, p)));
                report.FrameCounts[DatasetSplits.Name(split)] = frameCount;

                if (doc.CameraAngleX.HasValue)
                {
                    var angle = doc.CameraAngleX.Value;
                    if (!(angle > 0 && angle < Math.PI))
                        report.Problems.Add(DatasetProblem.Structure(file, -1, null,
                            "camera_angle_x = " + ValidationProblem.Format(angle) + " is not in (0, π); it is the horizontal field of view in radians."));
                    else if (firstAngle == null)
                    {
                        firstAngle = angle;
                        firstAngleFile = file;
                    }
                    else if (Math.Abs(angle - firstAngle.Value) > 1e-9)
                        report.Problems.Add(DatasetProblem.Structure(file, -1, null,
                            "camera_angle_x = " + ValidationProblem.Format(angle) + " differs from " + firstAngleFile + "'s " + ValidationProblem.Format(firstAngle.Value) +
                            "; bmild/nerf uses the last file's value for every split."));
                }
                if (frameCount == 0 && split == DatasetSplit.Train)
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null, "has no frames; every loader trains on the train split, so a dataset needs train views."));
                else if (frameCount == 0)
                    report.Warnings.Add(DatasetProblem.Structure(file, -1, null, "has no frames; " + LoadersNeeding(split) + " need frames in this split."));
                if (state.First != null && (doc.W.HasValue && doc.W != state.First.Width || doc.H.HasValue && doc.H != state.First.Height))
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null,
                        "w × h = " + Show(doc.W) + "×" + Show(doc.H) + " but the images are " + state.First.Width + "×" + state.First.Height +
                        "; instant-ngp and nerfstudio take the intrinsics from w and h (write the images' size)."));
                if (needsDepthScale && !(doc.IntegerDepthScale > 0))
                    report.Problems.Add(DatasetProblem.Structure(file, -1, null,
                        "frames have depth_path but integer_depth_scale is " + (doc.IntegerDepthScale.HasValue ? ValidationProblem.Format(doc.IntegerDepthScale.Value) : "missing") +
                        "; instant-ngp needs it above 0 (0.001 for millimetre PNGs)."));
            }
            var cloudWarnings = new List<ValidationProblem>();
            PointCloudOwnership.IsOwn(folder, config, cloudWarnings);
            foreach (var w in cloudWarnings) report.Warnings.Add(DatasetProblem.Structure(w.Field, -1, null, w.Reason + " " + w.Fix));
            GeometryPackChecks.Check(folder, config, state.SkipFiles, report);
            if (!state.SkipFiles)
            {
                if (state.First != null && state.ColourImages > 0 && state.SixteenBitColour == state.ColourImages)
                    report.Warnings.Add(DatasetProblem.Structure(state.FirstPath, -1, null,
                        "every colour image is 16-bit; loaders that divide by 255 (bmild/nerf, nerf-pytorch) read them up to 257 times too bright (write 8-bit PNGs, as Blender and this plugin do)."));
                foreach (var unreferenced in UnreferencedImages(folder, state.Referenced))
                    report.Warnings.Add(unreferenced);
            }
            foreach (var range in cameraCentres.Check())
                report.Warnings.Add(DatasetProblem.Structure("transforms_*.json", -1, null,
                    "(object size unknown here: the target is taken as a point at the origin) " + range));
            TimeDatasetChecks.Check(config.Config, report, timeFramesBySplit);
            if (labelMaps && !state.SkipFiles) LabelsValidation.Check(folder, report);
            return report;
        }

        static string Show(int? value) => value.HasValue ? value.Value.ToString(System.Globalization.CultureInfo.InvariantCulture) : "?";

        static string LoadersNeeding(DatasetSplit split)
        {
            switch (split)
            {
                case DatasetSplit.Train: return "all loaders";
                case DatasetSplit.Val: return "bmild/nerf, nerf-pytorch and nerfstudio (its default evaluation split)";
                default: return "bmild/nerf and nerf-pytorch";
            }
        }

        /// <summary>
        /// Image files in the split folders that no frame names — neither as its image or extra file, nor as a
        /// companion of one (<c>r_3_depth_0000.png</c> beside a referenced <c>r_3.png</c>, as nerf_synthetic's test
        /// split has): one warning per folder, because a loader never sees them.
        /// </summary>
        static IEnumerable<DatasetProblem> UnreferencedImages(string folder, HashSet<string> referenced)
        {
            var stems = new HashSet<string>(referenced.Select(r => r.Substring(0, r.Length - Path.GetExtension(r).Length)), StringComparer.OrdinalIgnoreCase);
            foreach (var split in DatasetSplits.Names)
            {
                var dir = Path.Combine(folder, split);
                if (!Directory.Exists(dir)) continue;
                var stray = Directory.EnumerateFiles(dir)
                    .Select(f => split + "/" + Path.GetFileName(f))
                    .Where(f => IsImage(f) && !referenced.Contains(f) && !IsCompanion(f, stems))
                    .OrderBy(f => f, StringComparer.Ordinal).ToList();
                if (stray.Count == 0) continue;
                yield return DatasetProblem.Structure(split + "/", -1, null,
                    stray.Count + " image(s) no frame names (" + string.Join(", ", stray.Take(3)) + (stray.Count > 3 ? ", …" : "") +
                    "); loaders never see them — a frame may be missing from " + DatasetLayout.TransformsFileName(split) + ".");
            }
        }

        static bool IsImage(string path)
        {
            var ext = Path.GetExtension(path);
            return string.Equals(ext, ".png", StringComparison.OrdinalIgnoreCase) || string.Equals(ext, ".exr", StringComparison.OrdinalIgnoreCase)
                || string.Equals(ext, ".jpg", StringComparison.OrdinalIgnoreCase) || string.Equals(ext, ".jpeg", StringComparison.OrdinalIgnoreCase);
        }

        static bool IsCompanion(string path, HashSet<string> stems)
        {
            var stem = path.Substring(0, path.Length - Path.GetExtension(path).Length);
            for (var cut = stem.IndexOf('_', stem.LastIndexOf('/') + 1); cut > 0; cut = stem.IndexOf('_', cut + 1))
                if (stems.Contains(stem.Substring(0, cut))) return true;
            return false;
        }

        sealed class ImageState
        {
            public bool SkipFiles;
            public readonly FramePathRegistry FilePaths = new FramePathRegistry();
            /// <summary>Dataset-relative paths (forward slashes) of every image a frame names.</summary>
            public readonly HashSet<string> Referenced = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
            /// <summary>What the file being read adds to <see cref="Referenced"/>, joined once it has read completely.</summary>
            public HashSet<string> NewlyReferenced = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
            public int ColourImages;
            public int SixteenBitColour;
            public PngInfo First;
            public string FirstPath;
        }

        /// <summary>What the frames of one file change, to undo when the file turns out to be malformed after some frames.</summary>
        sealed class Checkpoint
        {
            readonly DatasetValidationReport _report;
            readonly ImageState _state;
            readonly LoaderRangeCheck.Tally _centres;
            readonly int _images, _extras, _colour, _sixteen;
            readonly int? _width, _height;
            readonly PngInfo _first;
            readonly string _firstPath;
            public readonly int ProblemCount;
            public readonly HashSet<string> Referenced;

            public Checkpoint(DatasetValidationReport report, ImageState state, LoaderRangeCheck.Tally centres, DatasetSplit split)
            {
                _report = report;
                _state = state;
                _centres = centres;
                ProblemCount = report.Problems.Count;
                state.FilePaths.BeginFile(split);
                _images = report.ImagesChecked;
                _extras = report.ExtraFilesChecked;
                _width = report.ImageWidth;
                _height = report.ImageHeight;
                _colour = state.ColourImages;
                _sixteen = state.SixteenBitColour;
                _first = state.First;
                _firstPath = state.FirstPath;
                Referenced = state.NewlyReferenced = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
            }

            /// <summary>Undoes the file's additions; returns the camera centres' tally as it was before the file.</summary>
            public LoaderRangeCheck.Tally Restore()
            {
                _report.Problems.RemoveRange(ProblemCount, _report.Problems.Count - ProblemCount);
                _report.ImagesChecked = _images;
                _report.ExtraFilesChecked = _extras;
                _report.ImageWidth = _width;
                _report.ImageHeight = _height;
                _state.ColourImages = _colour;
                _state.SixteenBitColour = _sixteen;
                _state.First = _first;
                _state.FirstPath = _firstPath;
                _state.FilePaths.ForgetFile();
                Referenced.Clear();
                return _centres;
            }
        }

        static void CheckFrame(string folder, string file, DatasetFrame frame, ImageState state, DatasetValidationReport report)
        {
            void Problem(string message) => report.Problems.Add(DatasetProblem.Structure(file, frame.Index, frame.FilePath, message));
            foreach (var p in frame.Problems) Problem(p);

            if (frame.TransformMatrix.HasValue) CheckMatrix(frame.TransformMatrix.Value, Problem);

            if (frame.FilePath != null && frame.FilePath.EndsWith(".png", StringComparison.OrdinalIgnoreCase))
                Problem("file_path ends in .png; bmild/nerf, nerf-pytorch, nerfstudio and 3DGS append \".png\" themselves (write it without extension).");
            if (frame.FilePath != null && frame.FilePath.IndexOf('\\') >= 0)
                Problem("file_path uses '\\'; use forward slashes, which every OS and loader accepts.");
            if (state.SkipFiles) return;

            if (frame.FilePath != null)
            {
                // The one path rule (DatasetFile): inside the dataset through PathSafety, ".png" appended as the loaders do.
                var image = frame.Image;
                var relative = frame.FilePath.EndsWith(".png", StringComparison.OrdinalIgnoreCase) || (image.Exists && image.Relative == ExportPaths.Normalise(frame.FilePath))
                    ? frame.FilePath : frame.FilePath + ".png";
                if (!image.IsInside) Problem("file_path leaves the dataset folder.");
                else if (!image.Exists) Problem(ImageFormats.MissingPng(relative, image.FullPath));
                else
                {
                    state.NewlyReferenced.Add(image.Relative);
                    var info = ReadPng(image.FullPath, relative, Problem);
                    if (info != null)
                    {
                        report.ImagesChecked++;
                        state.ColourImages++;
                        if (info.BitDepth == 16) state.SixteenBitColour++;
                        if (state.First == null)
                        {
                            state.First = info;
                            state.FirstPath = relative;
                            report.ImageWidth = info.Width;
                            report.ImageHeight = info.Height;
                        }
                        else
                        {
                            if (info.Width != state.First.Width || info.Height != state.First.Height)
                                Problem("image " + relative + " is " + info.Width + "×" + info.Height + " but " + state.FirstPath + " is " +
                                        state.First.Width + "×" + state.First.Height + "; loaders stack all images and need one size.");
                            if (info.ColorType != state.First.ColorType || info.BitDepth != state.First.BitDepth)
                                Problem("image " + relative + " is " + info.Describe() + " but " + state.FirstPath + " is " + state.First.Describe() +
                                        "; loaders need one channel layout.");
                        }
                    }
                }
            }

            // One file under two keys (depth_path for instant-ngp, depth_file_path for nerfstudio) is checked and counted once.
            var checkedFiles = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
            foreach (var key in DatasetFolder.CheckedFileKeys)
            {
                var value = frame.FileKey(key);
                if (value == null) continue;
                var format = ExpectedFormat(key);
                if (value != null && !checkedFiles.Add(ExportPaths.Normalise(value) + "|" + format.Describe())) continue;
                var pair = new KeyValuePair<string, string>(key, value);
                var expected = ExpectedFormat(pair.Key);
                var named = frame.Named(key);
                var path = named.FullPath;
                if (!named.IsInside)
                {
                    Problem(pair.Key + " " + pair.Value + " leaves the dataset folder.");
                    continue;
                }
                if (!named.Exists)
                {
                    Problem(pair.Key + " " + pair.Value + " is missing.");
                    continue;
                }
                if (!pair.Value.EndsWith(".png", StringComparison.OrdinalIgnoreCase))
                {
                    Problem(pair.Key + " " + pair.Value + " is not a .png; this plugin's " + pair.Key + " files are " + expected.Describe() + " PNGs.");
                    continue;
                }
                state.NewlyReferenced.Add(ExportPaths.Normalise(pair.Value));
                var info = ReadPng(path, pair.Value, Problem);
                if (info == null) continue;
                report.ExtraFilesChecked++;
                if (info.BitDepth != expected.BitDepth || info.ColorType != expected.ColorType)
                    Problem(pair.Key + " " + pair.Value + " is " + info.Describe() + ", expected " + expected.Describe() + " (Documentation~/output-format.md).");
                if (state.First != null && (info.Width != state.First.Width || info.Height != state.First.Height))
                    Problem(pair.Key + " " + pair.Value + " is " + info.Width + "×" + info.Height + ", not the images' " + state.First.Width + "×" + state.First.Height + ".");
            }
        }

        sealed class Format
        {
            public int BitDepth;
            public int ColorType;
            public string Describe() => BitDepth + "-bit " + PngInfo.ColorTypeName(ColorType);
        }

        static Format ExpectedFormat(string key)
        {
            switch (key)
            {
                case "depth_path":
                case "depth_file_path": return new Format { BitDepth = 16, ColorType = PngInfo.ColorTypeGray };
                case "normal_path": return new Format { BitDepth = 8, ColorType = PngInfo.ColorTypeRgb };
                case LabelFrameKeys.Instance:
                case LabelFrameKeys.Semantic: return new Format { BitDepth = 16, ColorType = PngInfo.ColorTypeGray };
                // Motion blur's sharp image is written like the colour image it stands beside (issue 32 item 20).
                case MotionBlurKeys.SharpPath: return new Format { BitDepth = 8, ColorType = PngInfo.ColorTypeRgba };
                default: return new Format { BitDepth = 8, ColorType = PngInfo.ColorTypeGray };
            }
        }

        static PngInfo ReadPng(string path, string shown, Action<string> problem)
        {
            try
            {
                return PngInfo.Read(path);
            }
            catch (InvalidDataException e)
            {
                problem(ImageFormats.IsJpeg(path) ? ImageFormats.NotPng(shown) : shown + " " + e.Message);
            }
            catch (IOException e)
            {
                problem(shown + " cannot be read: " + e.Message);
            }
            catch (UnauthorizedAccessException e)
            {
                problem(shown + " cannot be read: " + e.Message);
            }
            return null;
        }

        static void CheckMatrix(Matrix4x4d m, Action<string> problem)
        {
            foreach (var p in PoseProblems(m)) problem(p);
        }

        /// <summary>
        /// Why <paramref name="m"/> is not a rigid camera-to-world pose (finite, last row 0 0 0 1, rotation orthonormal
        /// with determinant +1 within <see cref="RotationTolerance"/>); empty when it is one. Shared by validate and
        /// the converters' loader, so both accept exactly the same matrices.
        /// </summary>
        public static IReadOnlyList<string> PoseProblems(Matrix4x4d m)
        {
            var problems = new List<string>();
            if (!m.IsFinite)
            {
                problems.Add("transform_matrix has a NaN or infinite entry.");
                return problems;
            }
            if (m[3, 0] != 0 || m[3, 1] != 0 || m[3, 2] != 0 || m[3, 3] != 1)
                problems.Add("transform_matrix's last row is not [0, 0, 0, 1].");
            var worst = 0.0;
            for (var a = 0; a < 3; a++)
                for (var b = 0; b < 3; b++)
                {
                    var dot = Vector3d.Dot(m.Column(a), m.Column(b));
                    worst = Math.Max(worst, Math.Abs(dot - (a == b ? 1 : 0)));
                }
            var det = m.Determinant3x3;
            if (worst >= RotationTolerance)
                problems.Add("transform_matrix's rotation is not orthonormal (largest error of RᵀR − I: " + ValidationProblem.Format(worst) +
                             "); it is scaled or sheared, and loaders expect a rigid camera pose.");
            else if (Math.Abs(det - 1) >= RotationTolerance)
                problems.Add("transform_matrix's rotation has determinant " + ValidationProblem.Format(det) + ", not +1: it is mirrored (a left-handed pose, e.g. Unity's matrix without the Y/Z swap).");
            return problems;
        }
    }
}
