using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>evaluate &lt;dataset&gt; --inverse &lt;dir&gt;</c>: scores a relightable model's outputs of a split against the
    /// dataset's material, normal and relit truth with <see cref="InverseRenderingMetrics"/>. The folder holds, per view
    /// of the split named by its image's stem (<c>r_7</c>), any of (Documentation~/evaluate.md, "Inverse rendering"):
    /// <c>albedo/&lt;name&gt;.png|.exr</c> (linear diffuse albedo; PNG codes / 255 as TensoIR saves it),
    /// <c>normal/&lt;name&gt;.png|.exr</c> (world-space normals, output frame; PNG (n·0.5 + 0.5)·255),
    /// <c>roughness/&lt;name&gt;.png|.exr</c> (perceptual roughness, linear, first channel) and
    /// <c>relit/&lt;key&gt;/&lt;name&gt;.png</c> (the view under lighting condition &lt;key&gt;, sRGB).
    /// The truth is what the tensoir / r3dg exports hold: the diffuse albedo and roughness as 8-bit codes, the
    /// normal PNG with the colour image's alpha.
    /// </summary>
    public static class InverseRenderingEvaluator
    {
        public const string FileName = "inverse_rendering_metrics.json";
        public static readonly string[] Folders = { "albedo", "normal", "roughness", "relit" };

        /// <summary>Scores the folder and writes <see cref="FileName"/> into <paramref name="outFolder"/>; returns the JSON written.</summary>
        public static JObject Run(string datasetRoot, string folder, string split, string outFolder)
        {
            if (!Directory.Exists(folder) || !Folders.Any(f => Directory.Exists(Path.Combine(folder, f))))
                throw new InvalidParameterException(new[] { new ValidationProblem("--inverse", folder, "holds none of albedo/, normal/, roughness/, relit/<key>/.", "Write the model's outputs there, one file per " + split + " view named like its image (r_0.png).") });
            var views = InverseRenderingView.Read(datasetRoot).Where(v => v.Split == split).ToList();
            if (views.Count == 0)
                throw new InvalidParameterException(new[] { new ValidationProblem("--split", split, "has no views in the dataset.", "Name a split the dataset has.") });
            var json = new JObject { ["format"] = "nerf-dataset-inverse-rendering-metrics", ["split"] = split, ["views"] = views.Count };
            var images = views.Select(v => InverseRenderingImages.ReadRgba(v.ImagePath, "the masks come from its alpha.")).ToList();
            if (Directory.Exists(Path.Combine(folder, "albedo"))) json["albedo"] = Albedo(views, images, folder);
            if (Directory.Exists(Path.Combine(folder, "normal"))) json["normals"] = Normals(views, images, folder);
            if (Directory.Exists(Path.Combine(folder, "roughness"))) json["roughness"] = Roughness(views, images, folder);
            if (Directory.Exists(Path.Combine(folder, "relit"))) json["relit"] = Relit(views, folder, ProtocolBackground.For(datasetRoot));
            Directory.CreateDirectory(outFolder);
            var path = Path.Combine(outFolder, FileName);
            DatasetConverter.EnsureAbsent(path);
            FileOps.WriteNewText(path, ExportJson.Serialise(json));
            return json;
        }

        /// <summary>The prediction for a view in a subfolder: <c>&lt;name&gt;.exr</c>, else <c>&lt;name&gt;.png</c>; a missing one is refused, naming it.</summary>
        static string Prediction(string folder, string what, string stem)
        {
            foreach (var extension in new[] { ".exr", ".png" })
            {
                var path = Path.Combine(folder, what, stem + extension);
                if (File.Exists(path)) return path;
            }
            throw new InvalidParameterException(new[] { new ValidationProblem("--inverse", Path.Combine(folder, what, stem + ".png"), "is missing: every view of the split needs a file in " + what + "/ (or leave the folder out).", "Write it, named like the view's image.") });
        }

        /// <summary>Three values per pixel from an EXR's R, G, B or a PNG's first three channels (codes / 255), checked against the view's size.</summary>
        static double[] ReadRgb(string path, int width, int height, bool grey = false)
        {
            double[] values;
            int w, h;
            if (path.EndsWith(".exr", StringComparison.OrdinalIgnoreCase))
            {
                var exr = ExrReader.Read(path);
                w = exr.Width;
                h = exr.Height;
                var channels = grey ? new[] { exr.Channel("R") ?? exr.Channel("Y") } : new[] { exr.Channel("R"), exr.Channel("G"), exr.Channel("B") };
                if (channels.Any(c => c == null)) throw new InvalidDataException(path + ": has no " + (grey ? "R or Y" : "R, G and B") + " channels.");
                values = new double[w * h * channels.Length];
                for (var i = 0; i < w * h; i++)
                    for (var c = 0; c < channels.Length; c++) values[channels.Length * i + c] = channels[c][i];
            }
            else
            {
                var png = PngReader.Read(path);
                w = png.Width;
                h = png.Height;
                var take = grey ? 1 : 3;
                if (png.BitDepth != 8 || png.Channels < take) throw new InvalidDataException(path + ": is not an 8-bit " + (grey ? "grey or colour" : "RGB") + " PNG.");
                values = new double[w * h * take];
                for (var i = 0; i < w * h; i++)
                    for (var c = 0; c < take; c++) values[take * i + c] = png.Samples[png.Channels * i + c] / 255.0;
            }
            if (w != width || h != height)
                throw new InvalidParameterException(new[] { new ValidationProblem("--inverse", path, "is " + w + "×" + h + ", not the view's " + width + "×" + height + ".", "Render at the dataset's resolution.") });
            return values;
        }

        static JObject Albedo(IReadOnlyList<InverseRenderingView> views, IReadOnlyList<PngImage> images, string folder)
        {
            var albedo = new List<InverseRenderingMetrics.AlbedoView>();
            var diffuse = views.All(v => v.MetallicExr != null);
            for (var k = 0; k < views.Count; k++)
            {
                var v = views[k];
                var image = images[k];
                int w = image.Width, h = image.Height;
                var alpha = InverseRenderingImages.Alpha(image);
                var baseColour = InverseRenderingImages.ReadPass(v.AlbedoExr, MaterialKeys.AlbedoPath, w, h);
                var metallic = diffuse ? InverseRenderingImages.ReadPass(v.MetallicExr, MaterialKeys.MetallicPath, w, h) : null;
                // The truth as the tensoir export's albedo.png holds it, read as TensoIR reads it (ToTensor, blend over white).
                var codes = InverseRenderingImages.DiffuseLinear(baseColour, metallic, alpha);
                var truth = new double[w * h * 3];
                var mask = new bool[w * h];
                for (var i = 0; i < w * h; i++)
                {
                    var a = alpha[i] / 255.0;
                    mask[i] = alpha[i] != 0;
                    for (var c = 0; c < 3; c++) truth[3 * i + c] = codes[4 * i + c] / 255.0 * a + (1 - a);
                }
                albedo.Add(new InverseRenderingMetrics.AlbedoView { Truth = truth, Mask = mask, Prediction = ReadRgb(Prediction(folder, "albedo", v.Stem), w, h) });
            }
            var headline = InverseRenderingMetrics.AlbedoPsnr(albedo, InverseRenderingMetrics.AlbedoScaling.ThreeChannelGlobal, out var three);
            var single = InverseRenderingMetrics.AlbedoPsnr(albedo, InverseRenderingMetrics.AlbedoScaling.SingleChannelGlobal, out var one);
            return new JObject
            {
                ["psnr_tensoir_three_channel_global"] = Number(headline),
                ["psnr_single_channel_global"] = Number(single),
                ["psnr_three_channel_per_view"] = Number(InverseRenderingMetrics.AlbedoPsnr(albedo, InverseRenderingMetrics.AlbedoScaling.ThreeChannelPerView, out _)),
                ["psnr_single_channel_per_view"] = Number(InverseRenderingMetrics.AlbedoPsnr(albedo, InverseRenderingMetrics.AlbedoScaling.SingleChannelPerView, out _)),
                ["ratio_three_channel"] = new JArray(three.Select(Number)),
                ["ratio_single_channel"] = Number(one[0]),
                ["truth"] = diffuse ? "diffuse colour = base * (1 - metallic), linear 8-bit codes, blended over white by alpha" : "base colour (no metallic pass), linear 8-bit codes, blended over white by alpha",
                ["method"] = "TensoIR renderer.py: lower-median ratio truth / max(prediction, 1e-6) over the masked pixels of the views sampled by compute_rescale_ratio (or per view), aligned = clamp(ratio * prediction, 0, 1) in the mask and 1 outside, both ^(1/2.2), one MSE over all views",
            };
        }

        static JObject Normals(IReadOnlyList<InverseRenderingView> views, IReadOnlyList<PngImage> images, string folder)
        {
            var pairs = new List<(double[], double[], bool[])>();
            for (var k = 0; k < views.Count; k++)
            {
                var v = views[k];
                var image = images[k];
                int w = image.Width, h = image.Height;
                if (v.NormalPath == null || !File.Exists(v.NormalPath))
                    throw new InvalidParameterException(new[] { new ValidationProblem("normal_path", v.ImagePath, "has no normal pass to score normal/ against.", "Capture with normals on.") });
                var normal = PngReader.Read(v.NormalPath);
                if (normal.Width != w || normal.Height != h || normal.Channels < 3)
                    throw new InvalidParameterException(new[] { new ValidationProblem("normal_path", v.NormalPath, "is not an RGB image of the colour image's size.", "Re-capture the dataset.") });
                var alpha = InverseRenderingImages.Alpha(image);
                var truth = new double[w * h * 3];
                var mask = new bool[w * h];
                for (var i = 0; i < w * h; i++)
                {
                    // TensoIR :222–233: decode, blend with (0, 0, 1) by alpha, normalise.
                    var a = alpha[i] / 255.0;
                    mask[i] = alpha[i] != 0;
                    for (var c = 0; c < 3; c++) truth[3 * i + c] = (normal.Samples[normal.Channels * i + c] / 255.0 - 0.5) * 2 * a + (c == 2 ? 1 - a : 0);
                }
                var path = Prediction(folder, "normal", v.Stem);
                var predicted = ReadRgb(path, w, h);
                if (path.EndsWith(".png", StringComparison.OrdinalIgnoreCase))
                    for (var i = 0; i < predicted.Length; i++) predicted[i] = (predicted[i] - 0.5) * 2;
                pairs.Add((InverseRenderingMetrics.Normalise(truth), InverseRenderingMetrics.Normalise(predicted), mask));
            }
            return new JObject
            {
                ["mae_degrees_all_pixels"] = Number(InverseRenderingMetrics.NormalMaeDegrees(pairs, false)),
                ["mae_degrees_target"] = Number(InverseRenderingMetrics.NormalMaeDegrees(pairs, true)),
                ["method"] = "mean of arccos(clip(n_truth . n_prediction, -1, 1)) in degrees; all pixels as TensoIR renderer.py:470 (background truth +Z), or only where the colour image's alpha is not 0",
            };
        }

        static JObject Roughness(IReadOnlyList<InverseRenderingView> views, IReadOnlyList<PngImage> images, string folder)
        {
            var triples = new List<(double[], double[], double[])>();
            for (var k = 0; k < views.Count; k++)
            {
                var v = views[k];
                int w = images[k].Width, h = images[k].Height;
                var alpha = InverseRenderingImages.Alpha(images[k]);
                var pass = InverseRenderingImages.ReadPass(v.RoughnessExr, MaterialKeys.RoughnessPath, w, h);
                var truth = new double[w * h];
                var mask = new double[w * h];
                var r = pass.Channel("R");
                for (var i = 0; i < w * h; i++)
                {
                    mask[i] = alpha[i] / 255.0;
                    truth[i] = alpha[i] == 0 ? 0 : InverseRenderingImages.LinearCode(r[i]) / 255.0;
                }
                triples.Add((truth, ReadRgb(Prediction(folder, "roughness", v.Stem), w, h, grey: true), mask));
            }
            return new JObject
            {
                ["mse"] = Number(InverseRenderingMetrics.RoughnessMse(triples)),
                ["method"] = "R3DG eval_relighting_syn4.py: per view the mean over all pixels of (alpha * (prediction - truth))^2, the truth as _rough.png's codes / 255 and alpha the colour image's; then the mean over views",
            };
        }

        static JObject Relit(IReadOnlyList<InverseRenderingView> views, string folder, (string Name, byte R, byte G, byte B) background)
        {
            var result = new JObject();
            var keys = Directory.GetDirectories(Path.Combine(folder, "relit")).Select(Path.GetFileName).OrderBy(k => k, StringComparer.Ordinal).ToList();
            foreach (var key in keys)
            {
                var psnrs = new List<double>();
                var ssims = new List<double>();
                foreach (var v in views)
                {
                    if (!v.Relit.TryGetValue(key, out var truthPath))
                        throw new InvalidParameterException(new[] { new ValidationProblem("--inverse", Path.Combine(folder, "relit", key), "names a lighting condition the dataset's " + v.Stem + " has no relit image of (relit_paths).", "Name the folder by a key of the dataset's lights.json.") });
                    var truth = Composite(PngReader.Read(truthPath), background);
                    var predicted = PngReader.Read(Path.Combine(folder, "relit", key, v.Stem + ".png"));
                    if (predicted.Width != truth.width || predicted.Height != truth.height)
                        throw new InvalidParameterException(new[] { new ValidationProblem("--inverse", Path.Combine(folder, "relit", key, v.Stem + ".png"), "is " + predicted.Width + "×" + predicted.Height + ", not the view's size.", "Render at the dataset's resolution.") });
                    var p = Composite(predicted, background);
                    psnrs.Add(Psnr.Of(truth.rgb, p.rgb));
                    ssims.Add(Ssim.Mean(truth.rgb, p.rgb, truth.width, truth.height, 3));
                }
                result[key] = new JObject { ["psnr"] = Number(psnrs.Average()), ["ssim"] = Number(ssims.Average()), ["views"] = views.Count, ["background"] = background.Name };
            }
            return result;
        }

        /// <summary>An 8-bit image as RGB floats in [0, 1]: RGBA composited over the protocol background (AlphaCompositing.OverSolid), RGB as it is.</summary>
        static (float[] rgb, int width, int height) Composite(PngImage png, (string Name, byte R, byte G, byte B) background)
        {
            var n = png.Width * png.Height;
            var rgb = new byte[n * 3];
            if (png.Channels == 4) AlphaCompositing.OverSolid(png.Samples, rgb, n, background.R, background.G, background.B);
            else if (png.Channels == 3 && png.BitDepth == 8) Array.Copy(png.Samples, rgb, rgb.Length);
            else throw new InvalidDataException("an 8-bit RGB or RGBA PNG is expected, not " + png.Channels + " channels of " + png.BitDepth + " bits.");
            return (rgb.Select(b => b / 255f).ToArray(), png.Width, png.Height);
        }

        static JToken Number(double v) => double.IsNaN(v) || double.IsInfinity(v) ? JValue.CreateNull() : new JValue(v);
    }
}
