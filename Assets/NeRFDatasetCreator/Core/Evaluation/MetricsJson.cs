using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>metrics.json</c>: every figure per view and the mean over views, with the definitions used, so that a number
    /// copied into a paper says what it is. NaN and ±∞ (identical images: PSNR ∞) are written as null.
    /// </summary>
    public static class MetricsJson
    {
        public const string FileName = "metrics.json";

        /// <summary>The generator value that marks a metrics.json (and so its folder) as written by this tool.</summary>
        public const string Generator = PluginInfo.Name + " evaluate";

        public static readonly IReadOnlyDictionary<string, string> Definitions = new Dictionary<string, string>
        {
            ["psnr"] = "dB, 20·log10(1/√MSE) with MSE over every pixel and channel of the RGB images in [0, 1] (3DGS utils/image_utils.py psnr); the mean is over views, as 3DGS metrics.py averages per-image PSNR, leaving out views identical to the ground truth (PSNR +∞, null per view, counted in mean.identical_views)",
            ["ssim"] = "3DGS utils/loss_utils.py ssim: 11×11 Gaussian window σ 1.5 (normalised), 'same' conv2d with zero padding 5, C1 = 0.01², C2 = 0.03², per channel, mean over all pixels and channels, in double precision (3DGS metrics.py runs it in float32 and prints values up to ~2e-4 different: the 4th decimal may differ). Not scikit-image's default (7×7 uniform window, sample covariance, 3-pixel border cropped): see Documentation~/evaluate.md",
            ["psnr_masked"] = "PSNR over the pixels whose mask PNG value is ≥ 128 (the target's geometry), all three channels",
            ["depth"] = "against the dataset's z-depth (output units) on pixels with ground-truth surface and mask ≥ 128 where the render has a finite depth > 0: abs_rel = mean |d − d*|/d*, rmse = √mean (d − d*)², delta_1_25 = fraction with max(d/d*, d*/d) < 1.25; 'missing' counts the other surface pixels",
            ["normals"] = "angle in degrees between the render's and the dataset's normals (output world frame) on mask pixels where both are non-zero; mean and median",
            ["lpips"] = "not computed: LPIPS needs network weights this tool does not ship. 3DGS: python metrics.py -m <model> (LPIPS-VGG on renders/ and gt/, inputs [0, 1] unscaled); nerfstudio: ns-eval (LPIPS-AlexNet, inputs scaled to [-1, 1]); their figures are in trainer_metrics when found",
            ["error_map"] = "per pixel the mean absolute RGB difference, colour ramp saturating at 0.2",
            ["chamfer"] = "output units: accuracy = mean distance from reconstruction points to the nearest ground-truth point; completeness = mean distance from observed ground-truth points to the nearest reconstruction point; chamfer = (accuracy + completeness)/2 (DTU's mean)",
            ["fscore"] = "precision = share of reconstruction points within the threshold of the ground truth, recall = share of observed ground-truth points within the threshold of the reconstruction, F = 2PR/(P + R)",
        };

        public static JObject Build(EvaluationResult r)
        {
            var views = new JArray();
            foreach (var v in r.Views)
            {
                var view = new JObject
                {
                    ["frame"] = v.FrameIndex,
                    ["file_path"] = v.FilePath,
                    ["render"] = v.RenderPath,
                    ["psnr"] = Num(v.Psnr),
                    ["ssim"] = Num(v.Ssim),
                };
                if (r.HasMasks)
                {
                    view["psnr_masked"] = Num(v.MaskedPsnr);
                    view["mask_pixels"] = v.MaskPixels;
                }
                if (v.Depth != null) view["depth"] = Depth(v.Depth.AbsRel, v.Depth.Rmse, v.Depth.Delta125, v.Depth.Pixels, v.Depth.Missing);
                if (v.Normals != null) view["normals"] = new JObject { ["mean_degrees"] = Num(v.Normals.MeanDegrees), ["median_degrees"] = Num(v.Normals.MedianDegrees), ["pixels"] = v.Normals.Pixels };
                view["error_map"] = v.ErrorMapFile;
                views.Add(view);
            }

            var mean = new JObject
            {
                ["views"] = r.Views.Count,
                ["psnr"] = Num(FiniteMean(r.Views.Select(v => v.Psnr))),
                ["identical_views"] = r.Views.Count(v => double.IsPositiveInfinity(v.Psnr)),
                ["ssim"] = Num(Mean(r.Views.Select(v => v.Ssim))),
            };
            if (r.HasMasks) mean["psnr_masked"] = Num(FiniteMean(r.Views.Select(v => v.MaskedPsnr)));
            if (r.Views.Count > 0 && r.Views.All(v => v.Depth != null))
                mean["depth"] = Depth(MeanValid(r.Views.Select(v => v.Depth.AbsRel)), MeanValid(r.Views.Select(v => v.Depth.Rmse)), MeanValid(r.Views.Select(v => v.Depth.Delta125)),
                    r.Views.Sum(v => v.Depth.Pixels), r.Views.Sum(v => v.Depth.Missing));
            if (r.Views.Count > 0 && r.Views.All(v => v.Normals != null))
                mean["normals"] = new JObject
                {
                    ["mean_degrees"] = Num(MeanValid(r.Views.Select(v => v.Normals.MeanDegrees))),
                    ["median_degrees"] = Num(MeanValid(r.Views.Select(v => v.Normals.MedianDegrees))),
                    ["pixels"] = r.Views.Sum(v => v.Normals.Pixels),
                };

            var json = new JObject
            {
                ["generator"] = Generator,
                ["pluginVersion"] = PluginInfo.Version,
                ["createdUtc"] = r.CreatedUtc,
                ["dataset"] = r.DatasetFolder,
                ["split"] = r.Split,
                ["renders"] = new JObject
                {
                    ["folder"] = r.Renders.Folder,
                    ["layout"] = RenderLayouts.Name(r.Renders.Layout),
                    ["layout_source"] = RenderLayouts.Source(r.Renders.Layout),
                    ["depth_along_ray_converted"] = r.DepthAlongRay,
                },
                ["background"] = r.Background.Describe(),
                ["protocol"] = Protocol(r),
                ["warnings"] = new JArray(r.Warnings),
                ["notes"] = new JArray(r.Notes.Concat(r.Renders.Notes)),
                ["definitions"] = JObject.FromObject(Definitions),
                ["mean"] = mean,
                ["views"] = views,
            };
            if (r.Trainer != null) json["trainer_metrics"] = Trainer(r);
            if (r.SplitFile != null)
                json["split_file"] = new JObject
                {
                    ["file"] = SparseSplit.RelativePath(r.SplitFile.Name),
                    ["rule"] = r.SplitFile.Rule,
                    ["test"] = new JArray(r.SplitFile.Test.Select(i => (object)i).ToArray()),
                };
            if (r.Geometry != null) json["geometry"] = Geometry(r.Geometry);
            if (r.GeometrySteps.Count > 0)
            {
                // Per time step, and the mean over the steps (4D surface papers report per-frame Chamfer averaged over frames).
                json["geometry_steps"] = new JArray(r.GeometrySteps.Select(Geometry));
                json["geometry_mean_over_steps"] = GeometryMean(r.GeometrySteps);
            }
            return json;
        }

        /// <summary>The protocol evaluate followed: the dataset's eval_protocol.json (or none), and the renders' measured background.</summary>
        static JObject Protocol(EvaluationResult r)
        {
            var p = r.Protocol;
            var json = p == null
                ? new JObject { ["file"] = null, ["summary"] = "none: the dataset has no " + EvalProtocolFile.FileName + "; background white and split test by default" }
                : new JObject
                {
                    ["file"] = EvalProtocolFile.FileName,
                    ["summary"] = p.Describe(),
                    ["background"] = p.Background,
                    ["background_rgb"] = new JArray(p.R, p.G, p.B),
                    ["evaluation_split"] = p.EvaluationSplit,
                    ["resolution_factor"] = p.ResolutionFactor,
                    ["compositing"] = EvalProtocolTrainers.Compositing,
                    ["ssim"] = EvalProtocolTrainers.Ssim,
                    ["lpips"] = new JObject { ["network"] = EvalProtocolTrainers.LpipsNetwork, ["input_range"] = EvalProtocolTrainers.LpipsRange },
                };
            json["overridden"] = r.Warnings.Any(w => w.StartsWith("--override-protocol", StringComparison.Ordinal));
            var m = r.RenderBackground;
            json["renders_background"] = m == null || m.Pixels == 0 ? null : new JObject
            {
                ["mean_rgb"] = new JArray(Num(m.R), Num(m.G), Num(m.B)),
                ["pixels"] = m.Pixels,
                ["views"] = m.ViewsMeasured,
                ["rule"] = "the renders' mean colour where the ground truth's alpha is 0, on up to " + RenderBackgroundCheck.Views + " views; refused when a channel is more than " + RenderBackgroundCheck.Tolerance.ToString(System.Globalization.CultureInfo.InvariantCulture) + " from the background scored over (unless --override-protocol)",
            };
            return json;
        }

        /// <summary>The trainer's own figures beside ours, with the comparison rule and the views that disagree.</summary>
        static JObject Trainer(EvaluationResult r)
        {
            var t = r.Trainer;
            var json = new JObject
            {
                ["source"] = t.Source,
                ["file"] = t.File,
                ["method"] = t.Method,
                ["psnr"] = t.Psnr.HasValue ? Num(t.Psnr.Value) : null,
                ["ssim"] = t.Ssim.HasValue ? Num(t.Ssim.Value) : null,
                ["lpips"] = t.Lpips.HasValue ? Num(t.Lpips.Value) : null,
                ["ssim_variant"] = t.SsimVariant,
                ["lpips_variant"] = t.LpipsVariant,
                ["comparison"] = new JArray(r.TrainerMeans.Select(c => new JObject
                {
                    ["metric"] = c.Metric,
                    ["evaluate"] = Num(c.Ours),
                    ["trainer"] = Num(c.Theirs),
                    ["difference"] = Num(c.Theirs - c.Ours),
                    ["tolerance"] = c.Tolerance,
                    ["compared"] = c.Compared,
                    ["flagged"] = c.Flagged,
                })),
                ["flagged_views"] = new JArray(r.TrainerFlaggedViews),
                ["notes"] = new JArray(t.Notes),
            };
            if (t.Views != null)
                json["views"] = new JArray(t.Views.Select((v, i) => new JObject
                {
                    ["frame"] = i,
                    ["name"] = v.Name,
                    ["psnr"] = v.Psnr.HasValue ? Num(v.Psnr.Value) : null,
                    ["ssim"] = v.Ssim.HasValue ? Num(v.Ssim.Value) : null,
                    ["lpips"] = v.Lpips.HasValue ? Num(v.Lpips.Value) : null,
                }));
            return json;
        }

        /// <summary>The unweighted mean over time steps of each figure (each step counts once, whatever its point counts).</summary>
        public static JObject GeometryMean(IReadOnlyList<GeometryResult> steps) => new JObject
        {
            ["steps"] = new JArray(steps.Select(g => g.Step)),
            ["accuracy"] = Num(Mean(steps.Select(g => g.Distances.Accuracy))),
            ["completeness"] = Num(Mean(steps.Select(g => g.Distances.Completeness))),
            ["chamfer"] = Num(Mean(steps.Select(g => g.Distances.Chamfer))),
            ["precision"] = Num(Mean(steps.Select(g => g.Distances.Precision))),
            ["recall"] = Num(Mean(steps.Select(g => g.Distances.Recall))),
            ["fscore"] = Num(Mean(steps.Select(g => g.Distances.FScore))),
            ["rule"] = "mean over the time steps, each step once; each step against its own ground-truth mesh, observed points decided by that step's train views",
        };

        static JObject Geometry(GeometryResult g)
        {
            var d = g.Distances;
            var json = new JObject();
            if (g.Step.HasValue)
            {
                json["step"] = g.Step.Value;
                json[TimeKeys.Time] = g.Time.HasValue ? Num(g.Time.Value) : null;
            }
            foreach (var property in GeometryFigures(g, d).Properties()) json[property.Name] = property.Value;
            return json;
        }

        static JObject GeometryFigures(GeometryResult g, SurfaceDistances d)
        {
            return new JObject
            {
                ["reconstruction"] = g.ReconstructionPath,
                ["reconstruction_kind"] = g.ReconstructionKind,
                ["ground_truth"] = g.TruthPath,
                ["ground_truth_source"] = g.TruthSource,
                ["ground_truth_triangles"] = g.TruthTriangles,
                ["ground_truth_points"] = d.TruthPoints,
                ["observed_ground_truth_points"] = d.ObservedTruthPoints,
                ["observed_rule"] = g.ObservedRule,
                ["reconstruction_points"] = d.ReconstructionPoints,
                ["threshold"] = Num(d.Threshold),
                ["threshold_rule"] = g.ThresholdRule,
                ["accuracy"] = Num(d.Accuracy),
                ["completeness"] = Num(d.Completeness),
                ["chamfer"] = Num(d.Chamfer),
                ["precision"] = Num(d.Precision),
                ["recall"] = Num(d.Recall),
                ["fscore"] = Num(d.FScore),
                ["units"] = "output units (the frame of transform_matrix; divide by scene_normalisation.scale for Unity units)",
            };
        }

        static JObject Depth(double absRel, double rmse, double delta, long pixels, long missing) => new JObject
        {
            ["abs_rel"] = Num(absRel),
            ["rmse"] = Num(rmse),
            ["delta_1_25"] = Num(delta),
            ["pixels"] = pixels,
            ["missing"] = missing,
        };

        /// <summary>Mean of the values; +∞ when one is +∞ (an identical view), NaN for none.</summary>
        public static double Mean(IEnumerable<double> values)
        {
            double sum = 0;
            var n = 0;
            foreach (var v in values)
            {
                sum += v;
                n++;
            }
            return n == 0 ? double.NaN : sum / n;
        }

        /// <summary>
        /// The mean PSNR over views whose PSNR is finite: a view identical to the ground truth (PSNR +∞, counted as
        /// <c>identical_views</c>) would make any mean +∞.
        /// </summary>
        public static double FiniteMean(IEnumerable<double> values) => Mean(values.Where(v => !double.IsNaN(v) && !double.IsInfinity(v)));

        static double MeanValid(IEnumerable<double> values) => Mean(values.Where(v => !double.IsNaN(v)));

        public static JToken Num(double value) => double.IsNaN(value) || double.IsInfinity(value) ? JValue.CreateNull() : new JValue(value);

        public static string Text(JObject json)
        {
            using (var text = JsonNumbers.CreateText())
            {
                using (var writer = JsonNumbers.CreateWriter(text)) JsonNumbers.WriteToken(writer, json);
                return text.ToString() + "\n";
            }
        }
    }
}
