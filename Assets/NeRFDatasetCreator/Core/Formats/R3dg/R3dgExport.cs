using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to r3dg</c>: the dataset in R3DG's Synthetic4Relight layout (<see cref="R3dg"/>). Train colour is the
    /// true linear HDR colour (<c>hdr_path</c>) as float32 RGBA, straight alpha, RGB 0 where alpha is 0, with its mask;
    /// test colour the PNG with RGB 0 where alpha is 0 (R3DG masks test views by non-black RGB); <c>_albedo.png</c> the
    /// BASE colour sRGB-encoded (R3DG's base_color), <c>_rough.png</c> perceptual roughness linear, R = G = B; every relit
    /// test view in <c>test_rli/</c> and every environment (rotated) as <c>env_map/&lt;key&gt;.exr</c>.
    /// </summary>
    public static class R3dgExport
    {
        public static ConversionResult Write(ExportScene scene, string output, List<ValidationProblem> warnings, StagedOutput staged)
        {
            var root = scene.RootDirectory;
            var all = InverseRenderingView.Read(root);
            var views = all.Where(v => v.Split != "val").ToList();
            var lights = InverseRenderingLight.Read(root);
            int width = scene.Intrinsics.Width, height = scene.Intrinsics.Height;
            Refusals(views, width, height);
            if (all.Count > views.Count)
                warnings.Add(new ValidationProblem("val", (all.Count - views.Count) + " views", "are not exported: R3DG reads transforms_train.json and transforms_test.json only (dataset_readers.py:570–573).", "Nothing to do; they stay in the dataset."));
            if (output.IndexOf(R3dg.PathWord, StringComparison.Ordinal) < 0)
                warnings.Add(new ValidationProblem("output", output,
                    "does not contain the word Synthetic4Relight: R3DG picks this layout's reader by that word in its -s path (scene/__init__.py:51) and otherwise reads the folder as a Blender dataset, which finds no r_<i>.png.",
                    "Convert into a folder whose path contains Synthetic4Relight (the default <dataset>/Synthetic4Relight), or rename it."));
            var test = views.Where(v => v.Split == "test").ToList();
            var hasAlbedo = test.All(v => v.AlbedoExr != null);
            var hasRoughness = test.All(v => v.RoughnessExr != null);
            if (!hasAlbedo || !hasRoughness)
                warnings.Add(new ValidationProblem(!hasAlbedo ? MaterialKeys.AlbedoPath : MaterialKeys.RoughnessPath, "missing on test views",
                    "so _albedo.png / _rough.png are not written: R3DG's eval_relighting_syn4.py reads both (:174, :180).", "Capture with \"materials\" on."));
            var keys = test.SelectMany(v => v.Relit.Keys).Distinct(StringComparer.Ordinal).OrderBy(k => k, StringComparer.Ordinal).ToList();
            var environmentKeys = lights.Where(l => l.IsEnvironment).SelectMany(l => l.Rotations.Select(r => (light: l, rotation: r, key: l.Key(r)))).Where(e => keys.Contains(e.key)).ToList();
            var otherKeys = keys.Where(k => environmentKeys.All(e => e.key != k)).ToList();
            if (otherKeys.Count > 0)
                warnings.Add(new ValidationProblem(RelightingKeys.RelitPaths, string.Join(", ", otherKeys),
                    "are point or spot lights: their test_rli images are written, but R3DG's relighting evaluation lights the model with an environment map only (eval_relighting_syn4.py:82).", "Score them with nerf-dataset evaluate --inverse."));

            var written = new List<string>();
            string Dest(params string[] parts) => Path.Combine(new[] { output }.Concat(parts).ToArray());
            foreach (var v in views)
                if (v.Split == "train")
                {
                    written.Add(Dest("train", R3dg.TrainImage(v.Stem)));
                    written.Add(Dest("train", R3dg.TrainMask(v.Stem)));
                }
                else
                {
                    written.Add(Dest("test", R3dg.TestImage(v.Stem)));
                    if (hasAlbedo) written.Add(Dest("test", R3dg.Albedo(v.Stem)));
                    if (hasRoughness) written.Add(Dest("test", R3dg.Roughness(v.Stem)));
                    foreach (var key in v.Relit.Keys) written.Add(Dest(R3dg.RelitFolder, R3dg.Relit(key, v.Stem)));
                }
            written.AddRange(environmentKeys.Select(e => Dest(R3dg.EnvironmentFolder, e.key + ".exr")));
            foreach (var split in new[] { "train", "test" }) written.Add(Dest(DatasetLayout.TransformsFileName(split)));
            var points = scene.PointCloudPath != null ? Dest(BlenderDatasetLoader.PointCloudFileName) : null;
            if (points != null) written.Add(points);
            else warnings.Add(TensoIRExport.NoPoints("R3DG's Synthetic4Relight reader generates 100 000 random points in [−1.3, 1.3]³ (dataset_readers.py:579–591)"));
            written.Add(Dest(TensoIR.RecordFileName));
            foreach (var path in written) DatasetConverter.EnsureAbsent(path);

            foreach (var split in new[] { "train", "test" })
            {
                var frames = new JArray();
                foreach (var v in views.Where(x => x.Split == split))
                {
                    WriteView(v, output, width, height, hasAlbedo, hasRoughness, staged);
                    frames.Add(new JObject { ["file_path"] = "./" + split + "/" + v.Stem, ["transform_matrix"] = ExportJson.Matrix(v.CameraToWorld) });
                }
                staged.WriteNewText(Dest(DatasetLayout.TransformsFileName(split)), ExportJson.Serialise(new JObject { ["camera_angle_x"] = InverseRenderingView.CameraAngleX(root, split), ["frames"] = frames }));
            }
            var maps = new Dictionary<string, ExrImage>(StringComparer.Ordinal);
            foreach (var (light, rotation, key) in environmentKeys)
            {
                if (!maps.TryGetValue(light.Name, out var map)) maps[light.Name] = map = light.ReadMap();
                var rgb = InverseRenderingLight.Rotate(map, rotation);
                var rgba = new float[map.Width * map.Height * 4];
                for (var i = 0; i < map.Width * map.Height; i++)
                {
                    rgba[4 * i] = rgb[3 * i];
                    rgba[4 * i + 1] = rgb[3 * i + 1];
                    rgba[4 * i + 2] = rgb[3 * i + 2];
                    rgba[4 * i + 3] = 1;
                }
                staged.WriteNewBytes(Dest(R3dg.EnvironmentFolder, key + ".exr"), InverseRenderingImages.EncodeExrTopDown(rgba, map.Width, map.Height));
            }
            if (points != null) staged.Copy(Path.Combine(root, scene.PointCloudPath), points);
            var envKeys = environmentKeys.Select(e => e.key).ToList();
            if (envKeys.Count > 0)
                warnings.Add(new ValidationProblem("eval_relighting_syn4.py", string.Join(", ", envKeys),
                    "are this dataset's environments; R3DG's evaluation hard-codes envmap6 and envmap12 (:61–70) and a base-colour scale per scene folder, stopping with NotImplementedError for any other (:95–105).",
                    "Paste the lines of " + TensoIR.RecordFileName + " (config.r3dg_eval_relighting_syn4_py) into eval_relighting_syn4.py."));
            staged.WriteNewText(Dest(TensoIR.RecordFileName), ExportJson.Serialise(Record(output, hasAlbedo, hasRoughness, envKeys, points != null)));
            return new ConversionResult(output, output, written, warnings, new[]
            {
                "python train.py --eval -s " + output + " -m output/scene/3dgs   (R3DG stage 1; stage 2 -t neilf as its script/run_syn4.sh)",
            });
        }

        static void Refusals(IReadOnlyList<InverseRenderingView> views, int width, int height)
        {
            var problems = new List<ValidationProblem>();
            if (width != height)
                problems.Add(new ValidationProblem("resolution", width + "×" + height,
                    "is not square: R3DG's Synthetic4Relight reader computes the focal from the image's height as if it were the width (fovy = focal2fov(fov2focal(fovx, H), W), dataset_readers.py:557), so the cameras would be wrong.",
                    "Capture square images (width = height) for --to r3dg."));
            if (views.All(v => v.Split != "train") || views.All(v => v.Split != "test"))
                problems.Add(new ValidationProblem("splits", string.Join(", ", views.Select(v => v.Split).Distinct()), "lack train or test views: R3DG reads transforms_train.json and transforms_test.json (dataset_readers.py:570–573).", "Capture train and test views."));
            var missing = views.Where(v => v.Split == "train" && (v.HdrPath == null || !File.Exists(v.HdrPath))).ToList();
            if (missing.Count > 0)
                problems.Add(new ValidationProblem(HdrKeys.HdrPath, missing.Count + " of " + views.Count(v => v.Split == "train") + " train views (first: " + missing[0].Stem + ")",
                    "is missing: R3DG trains on linear HDR colour (<name>_rgb.exr, dataset_readers.py:570), made from each view's r_<i>_hdr.exr.",
                    "Capture with \"hdr\": { \"splits\": [\"train\"] } (Outputs ▸ Linear HDR colour)."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());
        }

        static void WriteView(InverseRenderingView v, string output, int width, int height, bool hasAlbedo, bool hasRoughness, StagedOutput staged)
        {
            var image = InverseRenderingImages.ReadRgba(v.ImagePath, "R3DG's masks come from the image's alpha.");
            if (image.Width != width || image.Height != height)
                throw new InvalidParameterException(new[] { new ValidationProblem("file_path", v.ImagePath, "is " + image.Width + "×" + image.Height + ", not the dataset's " + width + "×" + height + ".", "Re-capture the dataset.") });
            var alpha = InverseRenderingImages.Alpha(image);
            if (v.Split == "train")
            {
                var hdr = ExrReader.Read(v.HdrPath);
                if (hdr.Width != width || hdr.Height != height || hdr.Channel("R") == null)
                    throw new InvalidParameterException(new[] { new ValidationProblem(HdrKeys.HdrPath, v.HdrPath, "is not an RGB(A) EXR of the colour image's size.", "Re-capture the dataset.") });
                staged.WriteNewBytes(Path.Combine(output, "train", R3dg.TrainImage(v.Stem)), InverseRenderingImages.EncodeExrTopDown(InverseRenderingImages.LinearHdrRgba(hdr, alpha), width, height));
                staged.WriteNewBytes(Path.Combine(output, "train", R3dg.TrainMask(v.Stem)), PngWriter.Encode(alpha, width, height, PngPixelFormat.Gray8));
                return;
            }
            staged.WriteNewBytes(Path.Combine(output, "test", R3dg.TestImage(v.Stem)), PngWriter.Encode(InverseRenderingImages.BlackWhereTransparent(image), width, height, PngPixelFormat.Rgba8));
            if (hasAlbedo)
                staged.WriteNewBytes(Path.Combine(output, "test", R3dg.Albedo(v.Stem)),
                    PngWriter.Encode(InverseRenderingImages.BaseSrgb(InverseRenderingImages.ReadPass(v.AlbedoExr, MaterialKeys.AlbedoPath, width, height), alpha), width, height, PngPixelFormat.Rgba8));
            if (hasRoughness)
                staged.WriteNewBytes(Path.Combine(output, "test", R3dg.Roughness(v.Stem)),
                    PngWriter.Encode(InverseRenderingImages.GreyLinear(InverseRenderingImages.ReadPass(v.RoughnessExr, MaterialKeys.RoughnessPath, width, height), alpha), width, height, PngPixelFormat.Rgba8));
            foreach (var pair in v.Relit)
            {
                var relit = InverseRenderingImages.ReadRgba(pair.Value, "R3DG's evaluation takes the mask from its alpha (eval_relighting_syn4.py:142).");
                staged.WriteNewBytes(Path.Combine(output, R3dg.RelitFolder, R3dg.Relit(pair.Key, v.Stem)), PngWriter.Encode(InverseRenderingImages.BlackWhereTransparent(relit), relit.Width, relit.Height, PngPixelFormat.Rgba8));
            }
        }

        static JObject Record(string output, bool hasAlbedo, bool hasRoughness, IReadOnlyList<string> envKeys, bool points)
        {
            var taskDict = string.Join(", ", envKeys.Select(k => "\"" + k + "\": {\"capture_list\": [\"pbr\", \"pbr_env\", \"base_color\", \"roughness\"], \"envmap_path\": \"" + output + "/" + R3dg.EnvironmentFolder + "/" + k + ".exr\"}"));
            return new JObject
            {
                ["format"] = "nerf-dataset-inverse-rendering-export",
                ["target"] = "r3dg",
                ["rgb_exr"] = "train/<name>_rgb.exr: linear HDR colour (the dataset's r_<i>_hdr.exr), float32 RGBA, straight alpha, RGB 0 where alpha is 0; <name>_mask.png its alpha",
                ["rgba_png"] = "test/<name>_rgba.png: the scene's own lighting, sRGB, RGB 0 where alpha is 0 (R3DG masks test views by non-black RGB: a black pixel of the object is outside its mask)",
                ["albedo"] = hasAlbedo ? new JObject { ["file"] = "test/<name>_albedo.png", ["content"] = "base colour (not diffuse)", ["encoding"] = "sRGB, 8-bit, straight alpha" } : null,
                ["roughness"] = hasRoughness ? new JObject { ["file"] = "test/<name>_rough.png", ["content"] = "perceptual roughness = 1 - smoothness, R = G = B", ["encoding"] = "linear, 8-bit" } : null,
                ["lights"] = new JArray(envKeys.Select(k => new JObject { ["key"] = k, ["file"] = R3dg.EnvironmentFolder + "/" + k + ".exr", ["relit"] = R3dg.RelitFolder + "/" + k + "_<name>.png",
                    ["convention"] = "equirect float32, u = 0.5 - atan2(y, x) / (2 pi), top row +Z (Blender's world), already rotated" })),
                ["config"] = new JObject
                {
                    ["r3dg_eval_relighting_syn4_py"] = new JArray(
                        "task_dict = {" + taskDict + "}   (:61-70)",
                        "task_names = [" + string.Join(", ", envKeys.Select(k => "'" + k + "'")) + "]   (:78)",
                        "elif \"/<your scene folder>/\" in args.model_path: gaussians.base_color_scale = torch.tensor([1.0, 1.0, 1.0], dtype=torch.float32, device=\"cuda\")   (:95-105)"),
                },
                ["points"] = points ? BlenderDatasetLoader.PointCloudFileName : null,
            };
        }
    }
}
