using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to tensoir</c> (and <c>--to gs-ir</c>, the same files through GS-IR's Blender reader): the dataset in
    /// TensoIR-Synthetic's per-view layout (<see cref="TensoIR"/>). <c>rgba.png</c> is the scene's own lighting, each
    /// lighting condition its own <c>rgba_&lt;key&gt;.png</c> (an environment's rotation 0 also as <c>rgba_&lt;name&gt;.png</c>,
    /// the name TensoIR's relighting test, NeRFactor and GS-IR's relight_eval.py read); <c>albedo.png</c> is the DIFFUSE
    /// colour base × (1 − metallic), linear in 8 bits, because TensoIR-Synthetic's albedo is Blender's diffuse colour
    /// (NeRFactor render.py:213–230); <c>normal.png</c> the world-space normal with the colour image's alpha.
    /// Environments go to <c>env_maps/&lt;name&gt;.hdr</c> (and <c>&lt;name&gt;_&lt;rot&gt;.hdr</c> rotated), point lights to
    /// NeRFactor's <c>&lt;name&gt;.json</c> with <c>point_location</c> (render.py:198–209).
    /// </summary>
    public static class TensoIRExport
    {
        public static ConversionResult Write(ExportScene scene, string output, List<ValidationProblem> warnings, StagedOutput staged, bool gsIr = false)
        {
            var root = scene.RootDirectory;
            var target = gsIr ? "gs-ir" : "tensoir";
            var all = InverseRenderingView.Read(root);
            var views = all.Where(v => !gsIr || v.Split != "val").ToList();
            if (all.Count > views.Count)
                warnings.Add(new ValidationProblem("val", (all.Count - views.Count) + " views", "are not exported: GS-IR's Blender reader reads transforms_train.json and transforms_test.json only (scene/dataset_readers.py:285–290).", "Nothing to do; they stay in the dataset."));
            var lights = InverseRenderingLight.Read(root);
            Refusals(views, target);
            var width = scene.Intrinsics.Width;
            var height = scene.Intrinsics.Height;
            if (!gsIr && (width != TensoIR.EvaluationSide || height != TensoIR.EvaluationSide))
                warnings.Add(new ValidationProblem("resolution", width + "×" + height,
                    "is not 800×800: TensoIR's loaders fix img_wh = (800, 800) (tensoIR_rotation_setting.py:47) and its test renderer reshapes every view by it (renderer.py:179), so training reads metadata.json's imw/imh but evaluation breaks.",
                    "Capture at 800×800 for TensoIR's evaluation, or change img_wh in its loader."));
            var hasAlbedo = views.All(v => v.AlbedoExr != null);
            var hasMetallic = views.All(v => v.MetallicExr != null);
            var hasNormals = views.All(v => v.NormalPath != null && File.Exists(v.NormalPath));
            if (!hasAlbedo)
                warnings.Add(new ValidationProblem(MaterialKeys.AlbedoPath, views.Count(v => v.AlbedoExr == null) + " of " + views.Count + " views",
                    "have no albedo pass: albedo.png is not written, and TensoIR's test loaders read it (tensoIR_rotation_setting.py:206; GS-IR render.py:322 for --brdf_eval).",
                    "Capture with \"materials\" on (Documentation~/materials.md)."));
            else if (!hasMetallic)
                warnings.Add(new ValidationProblem(MaterialKeys.MetallicPath, "missing",
                    "so albedo.png holds the base colour: the diffuse colour base × (1 − metallic) TensoIR-Synthetic's albedo is needs the metallic pass.",
                    "Capture with the metallic pass (on by default with \"materials\")."));
            if (!hasNormals)
                warnings.Add(new ValidationProblem("normal_path", views.Count(v => v.NormalPath == null) + " of " + views.Count + " views",
                    "have no normal pass: normal.png is not written, and TensoIR's test loaders read it (tensoIR_rotation_setting.py:220; GS-IR normal_eval.py:39).",
                    "Capture with normals on (\"normal\": \"png\" per split)."));
            var keys = views.SelectMany(v => v.Relit.Keys).Distinct(StringComparer.Ordinal).OrderBy(k => k, StringComparer.Ordinal).ToList();
            var aliases = Aliases(lights, keys);
            if (keys.Count == 0)
                warnings.Add(new ValidationProblem(RelightingKeys.RelitPaths, "none",
                    gsIr ? "so only rgba.png (the scene's own lighting) is written: GS-IR trains on it, but its relighting evaluation compares against rgba_<light>.png of the test views (relight_eval.py:36)."
                         : "so only rgba.png (the scene's own lighting) is written: TensoIR's training loaders read rgba_<light_name>_<rot>.png (tensoIR_rotation_setting.py:120) or rgba_<light>.png (tensoIR_general_multi_lights.py:126); NeRFactor reads rgba.png.",
                    "Capture with \"relighting\" conditions (Documentation~/relighting.md)."));

            // Every destination is named before the first byte is written.
            var written = new List<string>();
            string Dest(params string[] parts) => Path.Combine(new[] { output }.Concat(parts).ToArray());
            foreach (var v in views)
            {
                var folder = TensoIR.ViewFolder(v.Split, v.Index);
                written.Add(Dest(folder, TensoIR.Metadata));
                written.Add(Dest(folder, TensoIR.Rgba));
                if (hasAlbedo) written.Add(Dest(folder, TensoIR.Albedo));
                if (hasNormals) written.Add(Dest(folder, TensoIR.Normal));
                foreach (var key in v.Relit.Keys) written.Add(Dest(folder, TensoIR.RelitFile(key)));
                foreach (var alias in aliases.Where(a => v.Relit.ContainsKey(a.Value))) written.Add(Dest(folder, TensoIR.RelitFile(alias.Key)));
            }
            var splits = views.Select(v => v.Split).Distinct().ToList();
            foreach (var split in splits) written.Add(Dest(DatasetLayout.TransformsFileName(split)));
            var lightFiles = LightFiles(lights, keys);
            written.AddRange(lightFiles.Select(f => Dest(TensoIR.LightsFolder, f.file)));
            var points = scene.PointCloudPath != null ? Dest(BlenderDatasetLoader.PointCloudFileName) : null;
            if (points != null) written.Add(points);
            else warnings.Add(NoPoints(gsIr ? "GS-IR's Blender reader generates 100 000 random points in [−1.3, 1.3]³ (scene/dataset_readers.py:299–310)" : "GS-IR and other Gaussian trainers reading this layout start from random points"));
            written.Add(Dest(TensoIR.RecordFileName));
            foreach (var path in written) DatasetConverter.EnsureAbsent(path);

            foreach (var split in splits)
            {
                var angle = InverseRenderingView.CameraAngleX(root, split);
                var frames = new JArray();
                foreach (var v in views.Where(x => x.Split == split))
                {
                    WriteView(v, output, angle, width, height, hasAlbedo, hasMetallic, hasNormals, aliases, staged);
                    frames.Add(new JObject { ["file_path"] = "./" + TensoIR.ViewFolder(v.Split, v.Index) + "/rgba", ["transform_matrix"] = ExportJson.Matrix(v.CameraToWorld) });
                }
                staged.WriteNewText(Dest(DatasetLayout.TransformsFileName(split)), ExportJson.Serialise(new JObject { ["camera_angle_x"] = angle, ["frames"] = frames }));
            }
            WriteLightFiles(lights, lightFiles, Path.Combine(output, TensoIR.LightsFolder), staged);
            if (points != null) staged.Copy(Path.Combine(root, scene.PointCloudPath), points);
            var record = Record(target, output, hasAlbedo, hasMetallic, hasNormals, lights, keys, aliases, lightFiles, views, points != null);
            staged.WriteNewText(Dest(TensoIR.RecordFileName), ExportJson.Serialise(record));
            if (gsIr) warnings.AddRange(GsIr.Warnings(views, keys.Concat(aliases.Keys).ToList()));
            return new ConversionResult(output, output, written, warnings, gsIr ? GsIr.Commands(output) : Commands(output, lights));
        }

        /// <summary>A warning for an export without the dataset's points3d.ply.</summary>
        internal static ValidationProblem NoPoints(string consequence) =>
            new ValidationProblem(BlenderDatasetLoader.PointCloudFileName, "missing from the dataset",
                "so the export has none: " + consequence + ".",
                "Capture with the point cloud on (\"pointCloud\" in the settings) so the export carries the target's surface points.");

        /// <summary>Refused before anything is written: too many views for NeRFactor's three digits, or views that are not RGBA.</summary>
        public static void Refusals(IReadOnlyList<InverseRenderingView> views, string target)
        {
            var problems = new List<ValidationProblem>();
            foreach (var split in views.GroupBy(v => v.Split))
                if (split.Count() > TensoIR.MaxViewsPerSplit)
                    problems.Add(new ValidationProblem(split.Key, split.Count() + " views",
                        "is more than 1000: the view folders are named " + split.Key + "_000 … " + split.Key + "_999, NeRFactor globs three digits ('%s_???', nerfactor/datasets/nerf.py:69) and TensoIR sorts the names as text (tensoIR_rotation_setting.py:44).",
                        "Capture at most 1000 views per split for --to " + target + "."));
            if (views.All(v => v.Split != "train") || views.All(v => v.Split != "test"))
                problems.Add(new ValidationProblem("splits", string.Join(", ", views.Select(v => v.Split).Distinct()), "lack train or test views: the loaders read train_NNN and test_NNN folders (tensoIR_rotation_setting.py:38).", "Capture train and test views."));
            InvalidParameterException.ThrowIfAny(problems.ToArray());
        }

        /// <summary>An environment's rotation 0 under its plain name too (rgba_sunset.png = rgba_sunset_000.png) unless a condition already has that key.</summary>
        internal static SortedDictionary<string, string> Aliases(IEnumerable<InverseRenderingLight> lights, ICollection<string> keys)
        {
            var aliases = new SortedDictionary<string, string>(StringComparer.Ordinal);
            foreach (var light in lights.Where(l => l.IsEnvironment && l.Rotations.Contains(0)))
                if (keys.Contains(light.Key(0)) && !keys.Contains(light.Name)) aliases[light.Name] = light.Key(0);
            return aliases;
        }

        static void WriteView(InverseRenderingView v, string output, double angle, int width, int height, bool hasAlbedo, bool hasMetallic, bool hasNormals,
            IDictionary<string, string> aliases, StagedOutput staged)
        {
            var folder = Path.Combine(output, TensoIR.ViewFolder(v.Split, v.Index));
            var image = InverseRenderingImages.ReadRgba(v.ImagePath, "NeRFactor asserts an RGBA image (nerf.py:159) and TensoIR reads four channels (tensoIR_rotation_setting.py:125).");
            if (image.Width != width || image.Height != height)
                throw new InvalidParameterException(new[] { new ValidationProblem("file_path", v.ImagePath, "is " + image.Width + "×" + image.Height + ", not the dataset's " + width + "×" + height + ".", "Re-capture the dataset.") });
            var alpha = InverseRenderingImages.Alpha(image);
            var metadata = new JObject
            {
                ["cam_transform_mat"] = string.Join(",", v.CameraToWorld.ToRows().SelectMany(r => r).Select(x => x.ToString("R", CultureInfo.InvariantCulture))),
                ["cam_angle_x"] = angle,
                ["imw"] = width,
                ["imh"] = height,
            };
            staged.WriteNewText(Path.Combine(folder, TensoIR.Metadata), ExportJson.Serialise(metadata));
            staged.Copy(v.ImagePath, Path.Combine(folder, TensoIR.Rgba));
            if (hasAlbedo)
            {
                var baseColour = InverseRenderingImages.ReadPass(v.AlbedoExr, MaterialKeys.AlbedoPath, width, height);
                var metallic = hasMetallic ? InverseRenderingImages.ReadPass(v.MetallicExr, MaterialKeys.MetallicPath, width, height) : null;
                staged.WriteNewBytes(Path.Combine(folder, TensoIR.Albedo), PngWriter.Encode(InverseRenderingImages.DiffuseLinear(baseColour, metallic, alpha), width, height, PngPixelFormat.Rgba8));
            }
            if (hasNormals)
            {
                var normal = PngReader.Read(v.NormalPath);
                if (normal.Width != width || normal.Height != height || normal.Channels < 3 || normal.BitDepth != 8)
                    throw new InvalidParameterException(new[] { new ValidationProblem("normal_path", v.NormalPath, "is not an 8-bit RGB image of the colour image's size.", "Re-capture the dataset.") });
                staged.WriteNewBytes(Path.Combine(folder, TensoIR.Normal), PngWriter.Encode(InverseRenderingImages.NormalWithAlpha(normal, alpha), width, height, PngPixelFormat.Rgba8));
            }
            foreach (var pair in v.Relit) staged.Copy(pair.Value, Path.Combine(folder, TensoIR.RelitFile(pair.Key)));
            foreach (var alias in aliases)
                if (v.Relit.TryGetValue(alias.Value, out var source)) staged.Copy(source, Path.Combine(folder, TensoIR.RelitFile(alias.Key)));
        }

        /// <summary>
        /// The light files: each environment unrotated as <c>&lt;name&gt;.hdr</c> (TensoIR's hdrdir, tensoIR_rotation_setting.py:82,
        /// rotates it itself) and every other rotation as <c>&lt;name&gt;_&lt;rot&gt;.hdr</c> (NeRFactor's test lights and GS-IR's
        /// --hdri name the images they are compared with by the file's name, render.py:190–192, relight.py:189); each point
        /// light as NeRFactor's <c>&lt;name&gt;.json</c> with <c>point_location</c> (render.py:198–209).
        /// </summary>
        internal static List<(InverseRenderingLight light, int? rotation, string file)> LightFiles(IEnumerable<InverseRenderingLight> lights, ICollection<string> keys)
        {
            var files = new List<(InverseRenderingLight, int?, string)>();
            foreach (var light in lights)
            {
                if (light.IsEnvironment)
                {
                    files.Add((light, 0, light.Name + ".hdr"));
                    foreach (var rotation in light.Rotations.Where(r => r != 0 && keys.Contains(light.Key(r)))) files.Add((light, rotation, light.Key(rotation) + ".hdr"));
                }
                else if (light.Kind == "point" && light.Position != null) files.Add((light, null, light.Name + ".json"));
            }
            return files;
        }

        internal static void WriteLightFiles(IEnumerable<InverseRenderingLight> lights, IEnumerable<(InverseRenderingLight light, int? rotation, string file)> files, string folder, StagedOutput staged)
        {
            var maps = new Dictionary<string, ExrImage>(StringComparer.Ordinal);
            foreach (var (light, rotation, file) in files)
            {
                var path = Path.Combine(folder, file);
                if (!light.IsEnvironment)
                {
                    staged.WriteNewText(path, ExportJson.Serialise(new JObject { ["point_location"] = new JArray(light.Position.Cast<object>().ToArray()) }));
                    continue;
                }
                if (!maps.TryGetValue(light.Name, out var map)) maps[light.Name] = map = light.ReadMap();
                var rgb = rotation == 0 ? InverseRenderingLight.Rgb(map) : InverseRenderingLight.Rotate(map, rotation.Value);
                staged.WriteNewBytes(path, RadianceHdr.Encode(rgb, map.Width, map.Height, 3));
            }
        }

        static List<string> Commands(string output, IEnumerable<InverseRenderingLight> lights)
        {
            var env = lights.FirstOrDefault(l => l.IsEnvironment);
            return new List<string>
            {
                "export PYTHONPATH=. && python train_tensoIR_rotated_multi_lights.py --config configs/multi_light_rotated/lego.txt --datadir " + output + " --hdrdir " + output + "/" + TensoIR.LightsFolder +
                (env != null ? " --light_name " + env.Name : "") + "   (TensoIR; paste the light lines of " + TensoIR.RecordFileName + " into the config)",
                "NeRFactor: data_root = " + output + " in its config; test lights in " + output + "/" + TensoIR.LightsFolder,
            };
        }

        static JObject Record(string target, string output, bool hasAlbedo, bool hasMetallic, bool hasNormals, IReadOnlyList<InverseRenderingLight> lights, IReadOnlyList<string> keys,
            IDictionary<string, string> aliases, IEnumerable<(InverseRenderingLight light, int? rotation, string file)> lightFiles, IReadOnlyList<InverseRenderingView> views, bool points)
        {
            var environments = lights.Where(l => l.IsEnvironment).ToList();
            var plainNames = keys.Where(k => !environments.Any(e => e.Rotations.Any(r => e.Key(r) == k))).Concat(aliases.Keys).Distinct().OrderBy(k => k, StringComparer.Ordinal).ToList();
            var config = new JObject();
            foreach (var env in environments)
                config["tensoir_rotated_" + env.Name] = new JArray(
                    "dataset_name = tensoIR_unknown_rotated_lights",
                    "datadir = " + output,
                    "hdrdir = " + output + "/" + TensoIR.LightsFolder,
                    "light_name = " + env.Name,
                    "light_rotation = [" + string.Join(", ", env.Rotations.Where(r => keys.Contains(env.Key(r))).Select(r => r.ToString("000", CultureInfo.InvariantCulture))) + "]");
            if (plainNames.Count > 0)
            {
                config["tensoir_general_multi_lights"] = new JArray(
                    "dataset_name = tensoIR_unknown_general_multi_lights",
                    "datadir = " + output,
                    "hdrdir = " + output + "/" + TensoIR.LightsFolder,
                    "light_name_list = [" + string.Join(", ", plainNames.Select(n => "\"" + n + "\"")) + "]");
                config["tensoir_relight_importance_py_370"] = "light_name_list= [" + string.Join(", ", plainNames.Select(n => "'" + n + "'")) + "]";
                config["gs_ir_relight_eval_py_24"] = "light_name_list = [" + string.Join(", ", plainNames.Select(n => "\"" + n + "\"")) + "]";
            }
            config["gs_ir_relight_eval_py_28"] = "num_test = " + views.Count(v => v.Split == "test");
            config["nerfactor"] = new JArray("data_root = " + output, "test light probes (.hdr) and OLAT lights (.json with point_location): " + output + "/" + TensoIR.LightsFolder);
            return new JObject
            {
                ["format"] = "nerf-dataset-inverse-rendering-export",
                ["target"] = target,
                ["rgba"] = "rgba.png: the scene's own lighting; rgba_<key>.png: the view under lighting condition <key> (lights/lights.json of the dataset); both straight RGBA, sRGB",
                ["albedo"] = hasAlbedo
                    ? new JObject
                    {
                        ["file"] = TensoIR.Albedo,
                        ["content"] = hasMetallic ? "diffuse colour = base colour * (1 - metallic)" : "base colour (the dataset has no metallic pass)",
                        ["encoding"] = "linear, clipped to 8 bits, no sRGB curve (round(255 v))",
                        ["alpha"] = "the colour image's alpha; RGB 0 where it is 0",
                    }
                    : null,
                ["normal"] = hasNormals
                    ? new JObject { ["file"] = TensoIR.Normal, ["content"] = "world-space unit normal n (output frame, Blender +Z up) as round((n * 0.5 + 0.5) * 255)", ["alpha"] = "the colour image's alpha" }
                    : null,
                ["relit_aliases"] = JObject.FromObject(aliases),
                ["lights"] = new JArray(lightFiles.Select(f => new JObject
                {
                    ["name"] = f.light.Name,
                    ["kind"] = f.light.Kind,
                    ["rotation_degrees"] = f.rotation,
                    ["file"] = TensoIR.LightsFolder + "/" + f.file,
                    ["convention"] = f.light.IsEnvironment ? "equirect, u = 0.5 - atan2(y, x) / (2 pi), top row +Z (Blender's world), rotated counter-clockwise about +Z seen from above" : "NeRFactor OLAT: point_location in the output world",
                })),
                ["config"] = config,
                ["points"] = points ? BlenderDatasetLoader.PointCloudFileName : null,
            };
        }
    }
}
