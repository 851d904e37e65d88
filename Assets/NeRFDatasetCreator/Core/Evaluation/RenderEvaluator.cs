using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading.Tasks;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset evaluate</c>: scores a trainer's renders of one split against the dataset's ground truth and
    /// writes <c>metrics.json</c>, one error map per view and <c>report.html</c> (<see cref="EvaluationOutput"/> says
    /// where it may write). Everything is checked — dataset, renders, sizes, geometry inputs — before the out folder is
    /// touched; views are scored in parallel (each view independently, so the figures do not depend on the thread count).
    /// </summary>
    public static class RenderEvaluator
    {
        public static EvaluationResult Run(EvaluationOptions options, Action<string> progress = null)
        {
            // The protocol first: it names the split and the background when the options do not (eval_protocol.json).
            var protocol = !string.IsNullOrEmpty(options.DatasetFolder) && Directory.Exists(options.DatasetFolder) ? EvalProtocolFile.Read(Path.GetFullPath(options.DatasetFolder)) : null;
            // --split sparse_<n> scores test views; otherwise the split named, else the protocol's, else test.
            var split = options.SplitFile != null ? "test" : options.Split ?? protocol?.EvaluationSplit ?? "test";
            var dataset = EvaluationDataset.Read(options.DatasetFolder, split);
            RenderSet renders;
            SparseSplit splitFile = null;
            var testViews = dataset.Frames.Count;
            if (options.SplitFile != null)
            {
                // --split sparse_<n>: only the test views the split file lists are scored.
                splitFile = SparseSplits.Find(dataset.Root, options.SplitFile);
                (dataset, renders) = SplitFileSelection.Select(dataset, splitFile, paths => RenderFolder.Read(options.RendersFolder, options.Layout, split, paths));
            }
            else renders = RenderFolder.Read(options.RendersFolder, options.Layout, split, dataset.Frames.Select(f => f.FilePath).ToList());
            var warnings = new List<string>();
            var background = EvaluationBackground.Parse(ProtocolChoice(options, protocol, warnings), dataset.Config);
            var stepsFolder = options.GeometryPath != null && Directory.Exists(options.GeometryPath);
            if (options.GeometryPath != null && !stepsFolder && !File.Exists(options.GeometryPath))
                throw new InvalidParameterException(new[] { new ValidationProblem("--geometry", options.GeometryPath, "does not exist.", "Pass the reconstruction as .ply (points or mesh) or .obj, or a folder of per-step reconstructions.") });
            if (stepsFolder && (options.Step.HasValue || options.TruthMeshPath != null))
                throw new InvalidParameterException(new[] { new ValidationProblem(options.Step.HasValue ? "--step" : "--gt-mesh", options.Step.HasValue ? options.Step.Value.ToString(CultureInfo.InvariantCulture) : options.TruthMeshPath,
                    "cannot be used with a folder of per-step reconstructions: each file's step comes from its name and its ground truth from the per-step geometry pack.", "Leave it out, or pass one reconstruction file.") });
            if (options.TruthMeshPath != null && !File.Exists(options.TruthMeshPath))
                throw new InvalidParameterException(new[] { new ValidationProblem("--gt-mesh", options.TruthMeshPath, "does not exist.", "Pass the target's mesh in the output frame (.ply or .obj).") });
            if (options.TruthMeshPath != null && options.GeometryPath == null)
                throw new InvalidParameterException(new[] { new ValidationProblem("--gt-mesh", options.TruthMeshPath, "is only used with --geometry.", "Add --geometry <reconstruction>, or leave --gt-mesh out.") });
            if (options.Threshold.HasValue && !(options.Threshold > 0))
                throw new InvalidParameterException(new[] { new ValidationProblem("--threshold", ValidationProblem.Format(options.Threshold.Value), "must be a distance > 0 in output units.", "Write e.g. --threshold 0.01.") });
            // The ground truth (and, for a dynamic dataset, the time step) is settled before anything is written.
            GeometryTruth truth = null;
            IReadOnlyList<KeyValuePair<string, GeometryTruth>> perStep = null;
            if (stepsFolder) perStep = GeometryStepsEvaluation.Match(dataset, options.GeometryPath);
            else if (options.GeometryPath != null) truth = GeometryTruth.Resolve(dataset, options.GeometryPath, options.TruthMeshPath, options.Step);
            var firstColumn = TrainTestExposureCrop.FirstColumn(dataset, renders);
            CheckSizes(dataset, renders, firstColumn, protocol);
            // The renders' own background, where the ground truth is transparent: another colour than the one scored over is refused (issue 35).
            var measured = RenderBackgroundCheck.Measure(dataset, renders, background, firstColumn);
            var wrongBackground = RenderBackgroundCheck.Problem(measured, background, dataset.Config);
            if (wrongBackground != null)
            {
                if (!options.OverrideProtocol)
                    throw new InvalidParameterException(new[] { new ValidationProblem("--background", background.Name, wrongBackground,
                        "Score them over the colour they were rendered on (--background <colour> --override-protocol when that contradicts eval_protocol.json), or train and render again with the protocol's trainer flags (eval_protocol.json trainer_flags).") });
                warnings.Add("--override-protocol: " + wrongBackground);
            }
            var trainer = TrainerResults.Find(options.TrainerMetricsPath, renders, Path.GetFullPath(options.RendersFolder), split, dataset.Frames.Count);

            var result = new EvaluationResult
            {
                DatasetFolder = dataset.Root,
                Split = split,
                SplitFile = splitFile,
                Protocol = protocol,
                RenderBackground = measured,
                Trainer = trainer,
                Renders = renders,
                Background = background,
                DepthAlongRay = options.DepthAlongRay,
                HasMasks = dataset.HasMasks,
                CreatedUtc = DateTime.UtcNow.ToString("yyyy-MM-dd'T'HH:mm:ss'Z'", CultureInfo.InvariantCulture),
            };
            var wantDepth = renders.Views.All(v => v.DepthPath != null);
            var wantNormals = renders.Views.All(v => v.NormalPath != null);
            if (wantDepth && !dataset.HasDepth) { wantDepth = false; result.Notes.Add("The renders include depth, but " + dataset.Unscored("depth", "depth_path", f => f.DepthPath) + ": depth not scored."); }
            if (wantNormals && !dataset.HasNormals) { wantNormals = false; result.Notes.Add("The renders include normals, but " + dataset.Unscored("normal", "normal_path", f => f.NormalPath) + ": normals not scored."); }
            if (firstColumn > 0)
                result.Notes.Add("The 3DGS renders are the right half of each view (render.py with --train_test_exp keeps columns W//2 … W − 1 of the render and of gt): scored against that half of the dataset's images, from column " + firstColumn + ".");
            if (splitFile != null) result.Notes.Add(SplitFileSelection.Note(splitFile, testViews));
            if (truth?.Note != null) result.Notes.Add(truth.Note);
            result.Warnings.AddRange(warnings);
            if (!dataset.HasMasks) result.Notes.Add("The dataset's " + split + " split has no masks: PSNR in the mask not computed.");
            if (renders.Layout == RenderLayout.Nerfstudio && wantDepth)
                result.Notes.Add(options.DepthAlongRay
                    ? "nerfstudio depth read as distance along each ray (nerfacto's) and converted to z-depth."
                    : "nerfstudio depth read as z-depth (splatfacto's); nerfacto's depth is the distance along the ray: pass --render-depth ray for it.");

            var outFolder = Path.GetFullPath(options.ResolvedOutFolder(Path.GetFullPath(options.RendersFolder), split));
            var created = !Directory.Exists(outFolder);
            EvaluationOutput.Prepare(outFolder, dataset.Root);
            result.OutFolder = outFolder;
            try
            {
                if (perStep != null)
                {
                    var missing = GeometryStepsEvaluation.Missing(dataset, perStep);
                    if (missing.Count > 0) result.Notes.Add("--geometry " + options.GeometryPath + " has no reconstruction for time step" + (missing.Count == 1 ? " " : "s ") + string.Join(", ", missing) + ": the geometry means are over the " + perStep.Count + " steps it has.");
                }
                ScoreAll(dataset, renders, background, wantDepth, wantNormals, options, outFolder, result, progress, truth, perStep, firstColumn);
            }
            catch
            {
                // A file that could only be found bad while scoring (a short depth array, a damaged PNG) stops the run:
                // the error maps it wrote go again, so the folder is as before (or gone, when this run made it).
                EvaluationOutput.RemoveWritten(outFolder, created);
                throw;
            }
            return result;
        }

        static void ScoreAll(EvaluationDataset dataset, RenderSet renders, EvaluationBackground background, bool wantDepth, bool wantNormals,
            EvaluationOptions options, string outFolder, EvaluationResult result, Action<string> progress,
            GeometryTruth truth = null, IReadOnlyList<KeyValuePair<string, GeometryTruth>> perStep = null, int firstColumn = 0)
        {
            var views = new ViewResult[renders.Views.Count];
            var done = 0;
            var parallel = new ParallelOptions { MaxDegreeOfParallelism = Math.Max(1, options.Threads) };
            try
            {
                Parallel.For(0, views.Length, parallel, i =>
                {
                    views[i] = Score(dataset, renders.Views[i], background, wantDepth, wantNormals, options, outFolder, firstColumn);
                    var n = System.Threading.Interlocked.Increment(ref done);
                    if (n % 10 == 0 || n == views.Length) progress?.Invoke("scored " + n + " of " + views.Length + " views");
                });
            }
            catch (AggregateException e)
            {
                // One view's own error (a refused image, a short file), not the parallel loop's wrapper.
                System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e.Flatten().InnerExceptions[0]).Throw();
            }
            result.Views.AddRange(views);

            if (perStep != null) result.GeometrySteps.AddRange(GeometryStepsEvaluation.Run(perStep, options.Threshold, options.TruthPoints, progress));
            else if (options.GeometryPath != null)
                result.Geometry = GeometryEvaluation.Run(truth ?? GeometryTruth.Resolve(dataset, options.GeometryPath, options.TruthMeshPath, options.Step), options.GeometryPath, options.Threshold, options.TruthPoints, progress);

            CompareTrainer(result);

            // The report first, metrics.json last: a metrics.json marks a complete evaluation.
            // Each written whole or not at all (AtomicFile); the journal goes last: a kill before leaves a folder the next run recognises.
            AtomicFile.WriteNewText(Path.Combine(outFolder, ReportHtml.FileName), ReportHtml.Build(result));
            AtomicFile.WriteNewText(Path.Combine(outFolder, MetricsJson.FileName), MetricsJson.Text(MetricsJson.Build(result)));
            EvaluationOutput.Finish(outFolder);
        }

        /// <summary>
        /// The background to score over: <c>--background</c>, else the protocol's, else white. A <c>--background</c> that
        /// contradicts the protocol is refused with the reason, or accepted with a warning under <c>--override-protocol</c>.
        /// </summary>
        static string ProtocolChoice(EvaluationOptions options, EvalProtocol protocol, List<string> warnings)
        {
            if (protocol != null && protocol.ResolutionFactor != 1)
                throw new InvalidParameterException(new[] { new ValidationProblem(EvalProtocolFile.FileName + ": resolution_factor", protocol.ResolutionFactor.ToString(CultureInfo.InvariantCulture),
                    "asks for renders at 1/" + protocol.ResolutionFactor.ToString(CultureInfo.InvariantCulture) + " of the dataset's resolution, but evaluate scores at the dataset's own resolution only.",
                    "Render at full resolution (and write resolution_factor 1), or compare the trainer's own figures with --trainer-metrics.") });
            var wanted = protocol?.EvaluationBackgroundName;
            if (options.Background == null) return wanted ?? "white";
            if (wanted == null || string.Equals(options.Background, wanted, StringComparison.OrdinalIgnoreCase)) return options.Background;
            var why = "the dataset's " + EvalProtocolFile.FileName + " says " + protocol.Describe() + ".";
            if (!options.OverrideProtocol)
                throw new InvalidParameterException(new[] { new ValidationProblem("--background", options.Background,
                    "contradicts the protocol: " + why + " Scored over another colour, a render made as the protocol says loses every background pixel (about 0.6–0.9 dB on nerf_synthetic-like data).",
                    "Leave --background out to score over " + wanted + ", or add --override-protocol to score over " + options.Background + " anyway (metrics.json and the report then say so).") });
            warnings.Add("--override-protocol: scored over " + options.Background + " although " + why);
            return options.Background;
        }

        /// <summary>The trainer's own figures beside evaluate's; a disagreement beyond the tolerance is a warning.</summary>
        static void CompareTrainer(EvaluationResult result)
        {
            var t = result.Trainer;
            if (t == null) return;
            // 3DGS metrics.py scores test/ only; ns-eval its own eval split.
            var comparable = !(t.Source == "3dgs metrics.py" && result.Split != "test");
            result.TrainerMeans.AddRange(TrainerComparison.Means(t, result.Views, comparable));
            foreach (var c in result.TrainerMeans.Where(c => c.Flagged)) result.Warnings.Add(TrainerComparison.Warning(t, c, result.Background));
            if (comparable) result.TrainerFlaggedViews.AddRange(TrainerComparison.FlaggedViews(t, result.Views));
        }

        /// <summary>Every render must have the ground truth's size (read from the PNG headers before any pixel is decoded).</summary>
        /// <param name="firstColumn">The renders hold the dataset's columns from here on (<see cref="TrainTestExposureCrop"/>).</param>
        static void CheckSizes(EvaluationDataset dataset, RenderSet renders, int firstColumn, EvalProtocol protocol = null)
        {
            // Every view is looked at (headers only), the first few named in frame order and the rest counted, so a
            // refusal never hides how many views are wrong (issue 35).
            const int Named = 5;
            var problems = new List<ValidationProblem>();
            var more = 0;
            void Add(ValidationProblem problem)
            {
                if (problems.Count < Named) problems.Add(problem);
                else more++;
            }
            foreach (var view in renders.Views.OrderBy(v => v.FrameIndex))
            {
                PngInfo truth, render;
                try { truth = PngInfo.Read(dataset.Frames[view.FrameIndex].ImagePath); }
                catch (InvalidDataException e) { Add(new ValidationProblem("<dataset>", dataset.Frames[view.FrameIndex].ImagePath, e.Message, "Run nerf-dataset validate on the dataset.")); continue; }
                try { render = PngInfo.Read(view.ColourPath); }
                catch (InvalidDataException e) { Add(new ValidationProblem("--renders", view.ColourPath, e.Message, "Re-render the view.")); continue; }
                if (render.Width != truth.Width - firstColumn || render.Height != truth.Height)
                    Add(new ValidationProblem("--renders", view.ColourPath, "is " + render.Width + "×" + render.Height + " but the ground truth " + view.FramePath + " is " + truth.Width + "×" + truth.Height + ".",
                        "Render at the dataset's resolution" + (protocol != null ? " (eval_protocol.json: resolution factor 1)" : "") + " (3DGS: -r 1 for images wider than 1600 px; nerfstudio: no --downscale-factor; nerf-pytorch: no --half_res)."));
            }
            if (more > 0)
                problems.Add(new ValidationProblem("--renders", renders.Folder, "has " + more + " more view(s) like these (" + (Named + more) + " of " + renders.Views.Count + " in all).",
                    "Render every view of the split at the dataset's resolution."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());
        }

        static ViewResult Score(EvaluationDataset dataset, RenderView view, EvaluationBackground background, bool wantDepth, bool wantNormals, EvaluationOptions options, string outFolder,
            int firstColumn = 0)
        {
            var frame = dataset.Frames[view.FrameIndex];
            // Every dataset-side image is cut to the columns the render holds (all of them unless 3DGS --train_test_exp).
            PngImage Truth(string path) => TrainTestExposureCrop.Columns(PngReader.Read(path), firstColumn);
            var truthPng = Truth(frame.ImagePath);
            var renderPng = PngReader.Read(view.ColourPath);
            int w = truthPng.Width, h = truthPng.Height;
            // The dataset's mask, depth and normals must match its own image before any pixel is compared (a mask of
            // another size used to end in "unexpected ArgumentException").
            PngImage TruthOfImageSize(string path, string what)
            {
                var png = Truth(path);
                if (png.Width != w || png.Height != h)
                    throw new InvalidParameterException(new[] { new ValidationProblem(Path.GetFileName(path), path, "is " + png.Width + "×" + png.Height + " but its frame's image " + frame.ImagePath + " is " + w + "×" + h + ".",
                        "Re-capture the " + what + ", or fix the frame's key so that it names this image's " + what + ".") });
                return png;
            }
            var truth = EvaluationImages.Colour(truthPng, background, frame.ImagePath);
            var render = EvaluationImages.Colour(renderPng, background, view.ColourPath);
            var result = new ViewResult
            {
                FrameIndex = view.FrameIndex,
                FilePath = view.FramePath,
                RenderPath = view.ColourPath,
                Width = w,
                Height = h,
                Psnr = Psnr.Of(render, truth),
                Ssim = Ssim.Mean(render, truth, w, h, 3),
            };
            byte[] mask = null;
            if (frame.MaskPath != null && dataset.HasMasks)
            {
                mask = EvaluationImages.Mask(TruthOfImageSize(frame.MaskPath, "mask"), frame.MaskPath);
                result.MaskedPsnr = Psnr.Masked(render, truth, 3, mask, out var inside);
                result.MaskPixels = inside;
            }
            if (wantDepth)
            {
                var truthDepth = EvaluationImages.DepthPng(TruthOfImageSize(frame.DepthPath, "depth"), dataset.DepthScale, frame.DepthPath);
                float[] renderDepth;
                if (view.DepthFormat == RenderDataFormat.NpyGz)
                    renderDepth = EvaluationImages.DepthNpy(NpyReader.ReadGz(view.DepthPath, (long)w * h), w, h, options.DepthAlongRay, dataset.Focal(w), dataset.Cx ?? w / 2.0, dataset.Cy ?? h / 2.0, view.DepthPath);
                else
                {
                    var png = PngReader.Read(view.DepthPath);
                    if (png.Width != w || png.Height != h) throw SizeProblem(view.DepthPath, png, w, h);
                    renderDepth = EvaluationImages.DepthPng(png, dataset.DepthScale, view.DepthPath);
                }
                result.Depth = DepthErrors.Compute(renderDepth, truthDepth, mask);
            }
            if (wantNormals)
            {
                var truthNormals = EvaluationImages.NormalsPng(TruthOfImageSize(frame.NormalPath, "normals"), frame.NormalPath);
                float[] renderNormals;
                if (view.NormalFormat == RenderDataFormat.NpyGz) renderNormals = EvaluationImages.NormalsNpy(NpyReader.ReadGz(view.NormalPath, 3L * w * h), w, h, view.NormalPath);
                else
                {
                    var png = PngReader.Read(view.NormalPath);
                    if (png.Width != w || png.Height != h) throw SizeProblem(view.NormalPath, png, w, h);
                    renderNormals = EvaluationImages.NormalsPng(png, view.NormalPath);
                }
                result.Normals = NormalErrors.Compute(renderNormals, truthNormals, mask);
            }

            var error = ErrorMap.Render(render, truth, w, h);
            var name = RenderFolder.BaseName(view.FramePath) + EvaluationOutput.ErrorSuffix;
            result.ErrorMapFile = EvaluationOutput.ErrorFolder + "/" + name;
            FileOps.WriteNewBytes(Path.Combine(outFolder, EvaluationOutput.ErrorFolder, name), PngWriter.Encode(error, w, h, PngPixelFormat.Rgb8));
            result.TruthThumbnail = Thumbnail(ErrorMap.ToBytes(truth), w, h, options.ThumbnailSize);
            result.RenderThumbnail = Thumbnail(ErrorMap.ToBytes(render), w, h, options.ThumbnailSize);
            result.ErrorThumbnail = Thumbnail(error, w, h, options.ThumbnailSize);
            return result;
        }

        static byte[] Thumbnail(byte[] rgb, int w, int h, int size)
        {
            var small = ErrorMap.Thumbnail(rgb, w, h, size, out var tw, out var th);
            return PngWriter.Encode(small, tw, th, PngPixelFormat.Rgb8);
        }

        static InvalidParameterException SizeProblem(string path, PngImage png, int w, int h) =>
            new InvalidParameterException(new[] { new ValidationProblem("--renders", path, "is " + png.Width + "×" + png.Height + " but the ground truth is " + w + "×" + h + ".", "Render at the dataset's resolution.") });
    }
}
