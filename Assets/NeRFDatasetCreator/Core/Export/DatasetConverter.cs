using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset convert &lt;dir&gt; --to nerfstudio|colmap|ngp|dynamic3dgs</c>: turns any Blender-format dataset (nerf_synthetic
    /// included) into another loader's format without touching the source. Default output locations:
    /// nerfstudio → <c>&lt;dir&gt;/transforms.json</c>; ngp → <c>&lt;dir&gt;/ngp/transforms.json</c>; colmap →
    /// <c>&lt;dir&gt;/colmap/</c> with <c>images/</c> (copies, flattened names) and <c>sparse/0/</c>; dynamic3dgs →
    /// <c>&lt;dir&gt;/dynamic3dgs/</c> (multi-view dynamic captures only). Nothing is ever
    /// overwritten: every destination is checked before the first byte is written, and the files are written into a
    /// working folder inside the output and moved into place only when all are complete (<see cref="StagedOutput"/>).
    /// </summary>
    public static class DatasetConverter
    {
        public const string ColmapFolderName = "colmap";

        /// <summary>Loads the Blender-format dataset in <paramref name="datasetDir"/> and exports it (see <see cref="Export"/>).</summary>
        /// <param name="depths">COLMAP only: also write 3DGS's inverse-depth maps and depth_params.json (<see cref="GaussianSplattingDepths"/>).</param>
        /// <param name="colmap">COLMAP only: binary or text, how many points, the minimum track length (null: the defaults).</param>
        /// <param name="objectNameOrId">nerfstudio only: mask every frame to this labelled object (<see cref="ObjectMaskExport"/>); null for none.</param>
        /// <param name="images">nerfstudio and ngp: copy, link or name the dataset's files (<see cref="ExportImages"/>); null: copy outside the dataset, relative inside.</param>
        /// <param name="background">colmap and nerfstudio: write RGB images composited over this colour, masks beside them (<see cref="BackgroundImages"/>); null: the dataset's images.</param>
        public static ConversionResult Convert(string datasetDir, ExportTarget target, string outDir = null, bool depths = false, ColmapOptions colmap = null,
            string objectNameOrId = null, ExportImages? images = null, ExportBackground background = null)
        {
            var warnings = new List<ValidationProblem>();
            var scene = BlenderDatasetLoader.Load(datasetDir, warnings);
            background = background?.Resolve(scene.RootDirectory);
            warnings.AddRange(LoaderRangeCheck.Check(scene.Frames.Select(f => f.Centre), 0));
            var time = target == ExportTarget.Dynamic3dgs || target == ExportTarget.Nerfies || target == ExportTarget.Dycheck || target == ExportTarget.Dynerf || target == ExportTarget.Replica || target == ExportTarget.Tum
                || target == ExportTarget.Kubric || target == ExportTarget.Nsff || target == ExportTarget.ShapeOfMotion ? null : TimeDatasetChecks.ConversionWarning(scene.Frames.Where(f => f.Split == "train").Select(f => f.Timing));
            if (time != null) warnings.Add(time);
            if (objectNameOrId != null && background != null)
                throw new InvalidParameterException(new[] { new ValidationProblem("--background", background.Name, "cannot be combined with --object, whose masks already name the pixels to train.", "Drop one of them.") });
            if (objectNameOrId != null) return ExportObject(scene, target, objectNameOrId, outDir, warnings, images);
            return Export(scene, target, outDir, null, null, warnings, depths, colmap, images, background);
        }

        /// <summary>Where <c>--object</c> writes: <paramref name="outDir"/>, or <c>&lt;dir&gt;/object_&lt;id&gt;</c> of the object named (resolved from labels.json).</summary>
        public static string ObjectOutputFolder(string root, string objectNameOrId, string outDir = null)
        {
            if (outDir != null) return Path.GetFullPath(outDir);
            var labels = Path.Combine(root, DatasetLayout.LabelsFileName);
            if (!File.Exists(labels)) return ObjectMaskExport.DefaultFolder(root, 0); // Convert refuses it with the reason
            return ObjectMaskExport.DefaultFolder(root, ObjectSelection.Find(LabelsJson.ReadFile(labels), objectNameOrId).Id);
        }

        /// <summary><c>--object</c>: a nerfstudio export whose masks keep one labelled object (<see cref="ObjectMaskExport"/>).</summary>
        static ConversionResult ExportObject(ExportScene scene, ExportTarget target, string objectNameOrId, string outDir, List<ValidationProblem> warnings, ExportImages? images)
        {
            if (target != ExportTarget.Nerfstudio)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(ObjectSelection.Option, objectNameOrId, "writes nerfstudio's per-frame mask_path, which --to " + ExportTargets.Name(target) + " has no place for.",
                        "Use --to nerfstudio --object …, or --to gaussian-grouping for masks of every object."),
                });
            var labelled = LabelledDataset.Load(scene, ObjectSelection.Option);
            var label = ObjectSelection.Find(labelled.Table, objectNameOrId);
            var output = outDir != null ? Path.GetFullPath(outDir) : ObjectMaskExport.DefaultFolder(scene.RootDirectory, label.Id);
            var staged = StagedOutput.Begin(output, "convert");
            try
            {
                var masks = new List<string>();
                var masked = ObjectMaskExport.WriteMasks(scene, labelled, label, output, warnings, staged, masks);
                var result = ToNerfstudio(masked, output, warnings, staged, References(ExportTarget.Nerfstudio, images, scene.RootDirectory, output));
                staged.Commit();
                return new ConversionResult(result.OutputDirectory, result.MainFile, result.WrittenFiles.Concat(masks).ToList(), result.Warnings, result.TrainCommands, result.FileReferences);
            }
            catch (Exception e) when (!staged.Placing && !(e is SimulatedStopException))
            {
                staged.Abandon();
                throw;
            }
        }

        /// <summary>
        /// Writes <paramref name="scene"/> in <paramref name="target"/>'s format: the path a fresh capture takes too.
        /// <paramref name="points"/> (output frame) fills COLMAP's points3D.txt; <paramref name="sceneRadius"/>
        /// (output units, e.g. s·b of the target) sets instant-ngp's aabb_scale (null: the scene's own, <see cref="AabbScale.ForDataset"/>).
        /// </summary>
        public static ConversionResult Export(ExportScene scene, ExportTarget target, string outDir = null,
            IReadOnlyList<CloudPoint> points = null, double? sceneRadius = null,
            List<ValidationProblem> warnings = null, bool depths = false, ColmapOptions colmap = null, ExportImages? images = null, ExportBackground background = null)
        {
            warnings = warnings ?? new List<ValidationProblem>();
            if (background != null) InvalidParameterException.ThrowIfAny(ExportBackground.Refusal(target, background));
            if (depths && target != ExportTarget.Colmap)
                throw new InvalidParameterException(new[] { new ValidationProblem("--depths", ExportTargets.Name(target), "is for --to colmap (3DGS reads depth maps for COLMAP sources).", "Drop --depths, or convert to colmap.") });
            if (colmap != null && target != ExportTarget.Colmap && target != ExportTarget.GaussianGrouping)
                throw new InvalidParameterException(new[] { new ValidationProblem("--binary, --points, --min-track", ExportTargets.Name(target), "shape the COLMAP model only.", "Drop them, or convert to colmap.") });
            // A lens the target cannot hold is refused before anything is written (LensExports).
            InvalidParameterException.ThrowIfAny(LensExports.Refusal(scene.Lens, target, depths), MotionBlurExports.Refusal(scene, target));
            warnings.AddRange(MotionBlurExports.Warnings(scene, target));
            var output = OutputFolder(scene.RootDirectory, target, outDir, background);
            var references = References(target, images, scene.RootDirectory, output);
            // Label exports need labels.json and every instance map: refused before the output folder is made.
            var labelled = target == ExportTarget.GaussianGrouping ? LabelledDataset.Load(scene, GaussianGroupingExport.What) : null;
            // Everything is written into a working folder inside the output and moved into place when complete (StagedOutput).
            var staged = StagedOutput.Begin(output, "convert");
            try
            {
                ConversionResult result;
                switch (target)
                {
                    case ExportTarget.Nerfstudio: result = background == null ? ToNerfstudio(scene, output, warnings, staged, references) : ToNerfstudio(scene, output, warnings, staged, references, background); break;
                    case ExportTarget.Ngp: result = ToNgp(scene, output, sceneRadius, warnings, staged, references); break;
                    case ExportTarget.Colmap: result = ToColmap(scene, output, points, warnings, depths, colmap ?? ColmapOptions.Default, staged, background); break;
                    case ExportTarget.Dynamic3dgs: result = Dynamic3DGaussiansExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.GaussianGrouping: result = GaussianGroupingExport.Write(scene, labelled, output, points, warnings, colmap, staged); break;
                    case ExportTarget.Nerfies: result = NerfiesExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Dycheck: result = DyCheckExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Llff: result = LlffExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Dynerf: result = DynerfExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Neus: result = NeusExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Replica: result = ReplicaExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Tum: result = TumRgbdExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Multiscale: result = MultiscaleExport.Write(scene, output, points, warnings, staged); break;
                    case ExportTarget.HdrNerf: result = HdrNerfExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Tensoir: result = TensoIRExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.GsIr: result = TensoIRExport.Write(scene, output, warnings, staged, gsIr: true); break;
                    case ExportTarget.R3dg: result = R3dgExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Kubric: result = KubricExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.Nsff: result = NsffExport.Write(scene, output, warnings, staged); break;
                    case ExportTarget.ShapeOfMotion: result = ShapeOfMotionExport.Write(scene, output, warnings, staged); break;
                    default: throw new ArgumentOutOfRangeException(nameof(target), target, "Unknown export target.");
                }
                EvalProtocolCarry.Copy(scene.RootDirectory, output, staged, warnings);
                staged.Commit();
                return result;
            }
            catch (Exception e) when (!staged.Placing && !(e is SimulatedStopException))
            {
                staged.Abandon();
                throw;
            }
        }

        /// <summary>Where <paramref name="target"/>'s export of the dataset in <paramref name="root"/> goes: <paramref name="outDir"/>, or the format's default place in the dataset.</summary>
        public static string OutputFolder(string root, ExportTarget target, string outDir = null, ExportBackground background = null)
        {
            if (outDir != null) return Path.GetFullPath(outDir);
            // --background: its own folder (<dir>/colmap_white, <dir>/nerfstudio_random, …), beside the plain export.
            if (background != null) return Path.GetFullPath(Path.Combine(root, ExportTargets.Name(target) + "_" + background.Resolve(root).Name));
            switch (target)
            {
                case ExportTarget.Ngp: return Path.GetFullPath(Path.Combine(root, NgpWriter.FolderName));
                case ExportTarget.Colmap: return Path.GetFullPath(Path.Combine(root, ColmapFolderName));
                case ExportTarget.Dynamic3dgs: return Path.GetFullPath(Path.Combine(root, Dynamic3DGaussians.FolderName));
                case ExportTarget.GaussianGrouping: return Path.GetFullPath(Path.Combine(root, GaussianGrouping.FolderName));
                case ExportTarget.Nerfies: return Path.GetFullPath(Path.Combine(root, Nerfies.FolderName));
                case ExportTarget.Dycheck: return Path.GetFullPath(Path.Combine(root, DyCheck.FolderName));
                case ExportTarget.Llff: return Path.GetFullPath(Path.Combine(root, Llff.FolderName));
                case ExportTarget.Dynerf: return Path.GetFullPath(Path.Combine(root, Dynerf.FolderName));
                case ExportTarget.Neus: return Path.GetFullPath(Path.Combine(root, Neus.FolderName));
                case ExportTarget.Replica: return Path.GetFullPath(Path.Combine(root, Replica.FolderName));
                case ExportTarget.Tum: return Path.GetFullPath(Path.Combine(root, TumRgbd.FolderName));
                case ExportTarget.Multiscale: return Path.GetFullPath(Path.Combine(root, MultiscaleExport.FolderName));
                case ExportTarget.HdrNerf: return Path.GetFullPath(Path.Combine(root, HdrNerf.FolderName));
                case ExportTarget.Tensoir: return Path.GetFullPath(Path.Combine(root, TensoIR.FolderName));
                case ExportTarget.GsIr: return Path.GetFullPath(Path.Combine(root, GsIr.FolderName));
                case ExportTarget.R3dg: return Path.GetFullPath(Path.Combine(root, R3dg.FolderName));
                case ExportTarget.Kubric: return Path.GetFullPath(Path.Combine(root, Kubric.FolderName));
                case ExportTarget.Nsff: return Path.GetFullPath(Path.Combine(root, Nsff.FolderName));
                case ExportTarget.ShapeOfMotion: return Path.GetFullPath(Path.Combine(root, ShapeOfMotion.FolderName));
                default: return Path.GetFullPath(root);
            }
        }

        /// <summary>
        /// How the export names the dataset's files: nerfstudio and ngp by <paramref name="images"/> (<see cref="ExportImagesModes.Resolve"/>);
        /// the other targets write their own images, so link and relative are refused for them.
        /// </summary>
        static ExportFileReferences References(ExportTarget target, ExportImages? images, string root, string output)
        {
            if (ExportImagesModes.NamesDatasetFiles(target)) return new ExportFileReferences(ExportImagesModes.Resolve(images, root, output), root, output);
            if (images.HasValue && images.Value != ExportImages.Copy)
                throw new InvalidParameterException(new[] { ImagesRefusal(target, images.Value) });
            return null;
        }

        /// <summary>The refusal of <c>--images link|relative</c> for a target that writes its own images.</summary>
        public static ValidationProblem ImagesRefusal(ExportTarget target, ExportImages images) =>
            new ValidationProblem("--images", ExportImagesModes.Name(images),
                "is for nerfstudio and ngp, whose transforms.json names the dataset's files; --to " + ExportTargets.Name(target) + " writes its own images into the export (renamed or re-encoded), so it is always self-contained.",
                "Leave --images out.");

        internal static ConversionResult ToNerfstudio(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged, ExportFileReferences references = null)
        {
            outDir = Path.GetFullPath(outDir);
            var file = Path.Combine(outDir, NerfstudioWriter.FileName);
            EnsureAbsent(file);
            warnings.AddRange(NerfstudioWriter.Warnings(scene));
            if (scene.InsideOut)
                warnings.Add(new ValidationProblem("camera_paths", NerfstudioWriter.FileName,
                    "belongs to an inside-out environment capture: the suggested commands let nerfstudio-data centre the poses on the mean camera and scale the cameras into ±1, nerfacto's uncontracted region, so the model's frame is not the file's.",
                    "Map camera_paths/*.json into the model's frame with the run's dataparser_transforms.json (Core's NerfstudioDataparserTransform) before ns-render, or train with the object flags (--center-method none --auto-scale-poses False) and accept a contracted room."));
            var text = ExportJson.Serialise(NerfstudioWriter.Build(scene, outDir, references));
            var placed = PlaceReferencedFiles(references, staged);
            staged.WriteNewText(file, text);
            return new ConversionResult(outDir, file, new[] { file }.Concat(CameraPathFiles.Write(scene, outDir, ExportTarget.Nerfstudio, warnings, staged)).Concat(placed).ToList(), warnings,
                scene.InsideOut
                    ? NerfstudioTraining.EnvironmentCommands(file, scene.Frames.Select(f => f.CameraToWorld.Translation).ToList(), scene.TargetReach)
                    : NerfstudioTraining.Commands(file, scene.TargetReach),
                references?.Describe());
        }

        /// <summary>nerfstudio with <c>--background</c>: the composites and masks first, then transforms.json naming the composites.</summary>
        static ConversionResult ToNerfstudio(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged, ExportFileReferences references, ExportBackground background)
        {
            var written = new List<string>();
            var composited = BackgroundImages.ForNerfstudio(scene, background, outDir, staged, warnings, written);
            var result = ToNerfstudio(composited, outDir, warnings, staged, references);
            return new ConversionResult(result.OutputDirectory, result.MainFile, result.WrittenFiles.Concat(written).ToList(), result.Warnings,
                BackgroundImages.Commands(result.TrainCommands, ExportTarget.Nerfstudio, background), result.FileReferences);
        }

        static ConversionResult ToNgp(ExportScene scene, string outDir, double? sceneRadius, List<ValidationProblem> warnings, StagedOutput staged, ExportFileReferences references)
        {
            outDir = Path.GetFullPath(outDir);
            var file = Path.Combine(outDir, NgpWriter.FileName);
            EnsureAbsent(file);
            var text = ExportJson.Serialise(NgpWriter.Build(scene, outDir, sceneRadius, warnings, references));
            var placed = PlaceReferencedFiles(references, staged);
            staged.WriteNewText(file, text);
            return new ConversionResult(outDir, file, new[] { file }.Concat(CameraPathFiles.Write(scene, outDir, ExportTarget.Ngp, warnings, staged)).Concat(placed).ToList(), warnings,
                null, references?.Describe());
        }

        /// <summary>Copies or links the files the JSON names into the export (<see cref="ExportFileReferences"/>), each checked absent first.</summary>
        static IReadOnlyList<string> PlaceReferencedFiles(ExportFileReferences references, StagedOutput staged)
        {
            if (references == null) return new string[0];
            foreach (var destination in references.Destinations) EnsureAbsent(destination);
            return references.Place(staged);
        }

        /// <param name="writeImage">Writes frame i's image to images/&lt;name&gt; (multiscale re-encodes it); null: copy the dataset's file.</param>
        internal static ConversionResult ToColmap(ExportScene scene, string outDir, IReadOnlyList<CloudPoint> points, List<ValidationProblem> warnings, bool depths, ColmapOptions options, StagedOutput staged,
            ExportBackground background = null, Action<int, string> writeImage = null)
        {
            outDir = Path.GetFullPath(outDir);
            var sparse = Path.Combine(outDir, "sparse", "0");
            var images = Path.Combine(outDir, ColmapTextWriter.ImagesFolder);
            var names = ColmapTextWriter.ImageNames(scene.Frames);
            var copies = scene.Frames.Select((f, i) => (from: Path.Combine(scene.RootDirectory, f.ImagePath), to: Path.Combine(images, names[i]))).ToList();
            var extension = options.Binary ? ".bin" : ".txt";
            var cameras = Path.Combine(sparse, "cameras" + extension);
            var imagesFile = Path.Combine(sparse, "images" + extension);
            var pointsFile = Path.Combine(sparse, "points3D" + extension);
            // 3DGS reads sparse/0/points3D.ply before points3D.txt; a copy of the real cloud keeps normals too.
            var pointsPly = scene.PointCloudPath == null ? null : Path.Combine(sparse, "points3D.ply");
            // 3DGS (upstream with llffhold 0, and forks that prefer it) takes its --eval test views from sparse/0/test.txt.
            var testNames = scene.Frames.Select((f, i) => f.Split == "test" ? names[i] : null).Where(n => n != null).ToList();
            var testTxt = testNames.Count > 0 ? Path.Combine(sparse, "test.txt") : null;
            var all = new List<string> { cameras, imagesFile, pointsFile };
            if (testTxt != null) all.Add(testTxt);
            if (pointsPly != null) all.Add(pointsPly);
            all.AddRange(copies.Select(c => c.to));
            // --background: the images are composites, their alpha goes to masks/ beside images/ (never inside it: gsplat
            // pairs the files of images/ by sorted name), and backgrounds.json records each image's colour.
            var composites = background == null ? null : scene.Frames.Select((f, i) => new BackgroundImages.Item
            {
                Source = copies[i].from,
                Image = copies[i].to,
                Mask = Path.Combine(outDir, BackgroundImages.MasksFolder, names[i]),
                DatasetPath = f.ImagePath,
            }).ToList();
            if (composites != null)
            {
                all.AddRange(composites.Select(c => c.Mask));
                all.Add(Path.Combine(outDir, BackgroundImages.RecordFileName));
            }
            GaussianSplattingDepths.DepthScan depthScan = null;
            if (depths)
            {
                // Every unusable depth file is named at once, before anything is written.
                var depthProblems = GaussianSplattingDepths.Check(scene.Frames, names).ToList();
                depthScan = GaussianSplattingDepths.Scan(scene, depthProblems);
                InvalidParameterException.ThrowIfAny(depthProblems.ToArray());
                all.AddRange(GaussianSplattingDepths.Destinations(outDir, names));
            }
            foreach (var path in all) EnsureAbsent(path);

            // Tracks only for the target's own surface sample: the fresh capture's points, or a points3d.ply that
            // PointCloudOwnership recognised (scene.PointCloudPath is set only then).
            var surface = points != null || scene.PointCloudPath != null;
            if (points == null && scene.PointCloudPath != null)
                points = PlyReader.Read(Path.Combine(scene.RootDirectory, scene.PointCloudPath));
            if (points == null)
            {
                points = RandomInitCloud.Cube(RandomInitCloud.DefaultCount, SceneNormalisation.GaussianSplattingInitHalfSize, 0);
                warnings.Add(new ValidationProblem(Path.GetFileName(pointsFile), points.Count + " random points",
                    "there is no point cloud, and 3DGS's COLMAP loader fails on an empty points3D file, so it holds the same uniform [−1.3, 1.3]³ cloud 3DGS would generate for the Blender layout (with empty tracks: random points are on no surface).",
                    "Export the target's surface point cloud from Unity for a better start."));
            }
            // A distorted dataset's tracks are projected through its lens (ColmapVisibility, ColmapPose.Project), as the
            // written camera images them.
            if (scene.Lens != null) warnings.Add(LensExports.ColmapWarning(scene.Lens));
            var model = ColmapModelBuilder.Build(scene, names, points, surface, options, warnings);

            if (composites != null) BackgroundImages.Write(composites, background, outDir, staged, warnings);
            else
                for (var i = 0; i < copies.Count; i++)
                    if (writeImage != null) writeImage(i, copies[i].to);
                    else staged.Copy(copies[i].from, copies[i].to);
            if (options.Binary)
            {
                staged.WriteNew(cameras, s => ColmapBinaryWriter.WriteCameras(s, scene.Intrinsics, scene.Lens));
                staged.WriteNew(imagesFile, s => ColmapBinaryWriter.WriteImages(s, model));
                staged.WriteNew(pointsFile, s => ColmapBinaryWriter.WritePoints3D(s, model));
            }
            else
            {
                staged.WriteNewText(cameras, ColmapTextWriter.CamerasText(scene.Intrinsics, scene.Lens));
                staged.WriteNew(imagesFile, s => WriteText(s, w => ColmapTextWriter.WriteImages(w, model)));
                staged.WriteNew(pointsFile, s => WriteText(s, w => ColmapTextWriter.WritePoints3D(w, model)));
            }
            if (testTxt != null) staged.WriteNewText(testTxt, string.Join("\n", testNames) + "\n");
            if (pointsPly != null) staged.Copy(Path.Combine(scene.RootDirectory, scene.PointCloudPath), pointsPly);
            if (depths) GaussianSplattingDepths.Write(scene, names, outDir, warnings, staged, depthScan);
            if (scene.Frames.Any(f => f.Split != "train"))
                warnings.Add(new ValidationProblem(Path.GetFileName(imagesFile), scene.Frames.Count + " images",
                    "COLMAP has no splits: train, val and test views are all listed; upstream 3DGS's --eval holds out every 8th image by name (sparse/0/test.txt lists the real test views for loaders that read it).",
                    "For the nerf_synthetic protocol, train 3DGS on the Blender layout itself (train.py -s <dir> --eval)."));
            var commands = ColmapTraining.Commands(outDir, depths, model);
            return new ConversionResult(outDir, outDir, all, warnings, background == null ? commands : BackgroundImages.Commands(commands, ExportTarget.Colmap, background));
        }

        static void WriteText(Stream stream, Action<TextWriter> write)
        {
            using (var writer = new StreamWriter(stream, new System.Text.UTF8Encoding(false), 1 << 16))
                write(writer);
        }

        /// <summary>The field a refused destination is named by: what the user chooses with <c>--out</c> (or the export's default place).</summary>
        public const string ExportOutputField = "output";

        /// <summary>Refuses, naming it, a destination that exists: convert never overwrites (every export checks before writing).</summary>
        internal static void EnsureAbsent(string path)
        {
            if (File.Exists(path) || Directory.Exists(path))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(ExportOutputField, path, "already exists (an earlier convert?); convert never overwrites files.",
                        "Move or delete it, or convert into another folder (--out <folder>)."),
                });
        }

    }
}
