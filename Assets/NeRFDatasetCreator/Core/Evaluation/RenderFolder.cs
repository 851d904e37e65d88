using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Finds a trainer's renders of one split, in the layout named or the one the folder has, and pairs them with the
    /// split's frames. Refuses — with the file, the reason and the fix — when counts or names do not match the split;
    /// image sizes are checked when the images are read (<see cref="RenderEvaluator"/>). Each layout follows the
    /// trainer's own code (<see cref="RenderLayouts.Source"/>).
    /// </summary>
    public static class RenderFolder
    {
        /// <param name="renders">The folder given with --renders.</param>
        /// <param name="layout">The layout named with --layout, or null to detect it.</param>
        /// <param name="split">"train", "val" or "test".</param>
        /// <param name="framePaths">The split's <c>file_path</c> values, in file order.</param>
        public static RenderSet Read(string renders, RenderLayout? layout, string split, IReadOnlyList<string> framePaths)
        {
            if (string.IsNullOrEmpty(renders) || !Directory.Exists(renders))
                throw Problem(renders ?? "", "is not an existing folder.", "Pass the folder the trainer rendered into (3DGS: the model folder; nerfstudio: ns-render's --output-path; instant-ngp: --screenshot_dir).");
            var root = Path.GetFullPath(renders);
            var detected = layout ?? Detect(root, split, framePaths);
            if (detected == null)
                throw Problem(root, "holds no renders of the " + split + " split in a layout this tool knows: looked for " + split + "/ours_<iter>/renders/00000.png (3DGS render.py), " +
                                    split + "/rgb/<name>.png (nerfstudio ns-render dataset), testset_<iter>/000.png (nerf-pytorch) and " + BaseName(framePaths.FirstOrDefault() ?? "r_0") + ".png (instant-ngp screenshots, plain).",
                    "Point --renders at the trainer's output folder, or name the layout with --layout " + string.Join("|", RenderLayouts.Names) + ".");
            switch (detected.Value)
            {
                case RenderLayout.GaussianSplatting: return GaussianSplatting(root, split, framePaths);
                case RenderLayout.Nerfstudio: return Nerfstudio(root, split, framePaths);
                case RenderLayout.NerfPytorch: return NerfPytorchRenders.Read(root, split, framePaths);
                default: return ByName(root, split, framePaths, detected.Value);
            }
        }

        /// <summary>The name a frame's render carries: the last segment of file_path without a .png extension (r_0 for ./test/r_0).</summary>
        public static string BaseName(string framePath)
        {
            var name = (framePath ?? "").Replace('\\', '/');
            var slash = name.LastIndexOf('/');
            if (slash >= 0) name = name.Substring(slash + 1);
            if (name.EndsWith(".png", StringComparison.OrdinalIgnoreCase)) name = name.Substring(0, name.Length - 4);
            return name;
        }

        static RenderLayout? Detect(string root, string split, IReadOnlyList<string> framePaths)
        {
            if (GaussianIterationFolders(Path.Combine(root, split)).Count > 0 || IsGaussianIterationFolder(root)) return RenderLayout.GaussianSplatting;
            if (Directory.Exists(Path.Combine(root, split, "rgb")) || Directory.Exists(Path.Combine(root, "rgb"))) return RenderLayout.Nerfstudio;
            if (NerfPytorchRenders.Holds(root)) return RenderLayout.NerfPytorch;
            var first = BaseName(framePaths.FirstOrDefault() ?? "");
            if (first.Length > 0 && (File.Exists(Path.Combine(root, first + ".png")) || File.Exists(Path.Combine(root, split, first + ".png")))) return RenderLayout.Plain;
            return null;
        }

        static bool IsGaussianIterationFolder(string folder) =>
            Path.GetFileName(folder).StartsWith("ours_", StringComparison.Ordinal) && Directory.Exists(Path.Combine(folder, "renders"));

        /// <summary>The <c>ours_&lt;iter&gt;</c> folders holding <c>renders/</c>, by iteration.</summary>
        static List<(int iteration, string folder)> GaussianIterationFolders(string splitFolder)
        {
            var result = new List<(int, string)>();
            if (!Directory.Exists(splitFolder)) return result;
            foreach (var folder in Directory.GetDirectories(splitFolder, "ours_*"))
                if (int.TryParse(Path.GetFileName(folder).Substring(5), NumberStyles.None, CultureInfo.InvariantCulture, out var iteration) && Directory.Exists(Path.Combine(folder, "renders")))
                    result.Add((iteration, folder));
            result.Sort((a, b) => a.Item1.CompareTo(b.Item1));
            return result;
        }

        static RenderSet GaussianSplatting(string root, string split, IReadOnlyList<string> framePaths)
        {
            var notes = new List<string>();
            string iterationFolder;
            if (IsGaussianIterationFolder(root)) iterationFolder = root;
            else
            {
                var iterations = GaussianIterationFolders(Path.Combine(root, split));
                if (iterations.Count == 0)
                    throw Problem(Path.Combine(root, split), "has no ours_<iter>/renders folder: 3DGS render.py writes <model>/" + split + "/ours_<iter>/renders/00000.png." +
                                                             (split == "val" ? " 3DGS reads only transforms_train.json and transforms_test.json, so it never renders val." : ""),
                        "Run python render.py -m <model> (add --skip_train to render only test) and pass the model folder.");
                iterationFolder = iterations[iterations.Count - 1].folder;
                if (iterations.Count > 1)
                    notes.Add("3DGS: " + iterations.Count + " iterations rendered (" + string.Join(", ", iterations.Select(i => Path.GetFileName(i.folder))) + "); evaluating the latest, " +
                              Path.GetFileName(iterationFolder) + ", as render.py's --iteration -1 loads the latest. Pass that ours_<iter> folder to pick another.");
            }
            var folder = Path.Combine(iterationFolder, "renders");
            var files = Directory.GetFiles(folder).Select(Path.GetFileName).Where(n => !n.StartsWith(".", StringComparison.Ordinal)).ToList();
            var numbered = new SortedDictionary<int, string>();
            var strangers = new List<string>();
            foreach (var name in files)
            {
                if (name.Length == 9 && name.EndsWith(".png", StringComparison.Ordinal) &&
                    int.TryParse(name.Substring(0, 5), NumberStyles.None, CultureInfo.InvariantCulture, out var idx)) numbered[idx] = name;
                else if (name.Length > 9 && name.EndsWith(".png", StringComparison.Ordinal) &&
                         int.TryParse(name.Substring(0, name.Length - 4), NumberStyles.None, CultureInfo.InvariantCulture, out idx) && idx >= 100000) numbered[idx] = name;
                else strangers.Add(name);
            }
            if (strangers.Count > 0)
                throw Problem(folder, "holds " + Describe(strangers) + ", which 3DGS render.py does not write (it names renders 00000.png, 00001.png, … in the split's order).",
                    "Pass the renders folder exactly as render.py wrote it.");
            if (numbered.Count != framePaths.Count || (numbered.Count > 0 && numbered.Keys.Last() != numbered.Count - 1))
                throw Problem(folder, "holds " + numbered.Count + " renders" + (numbered.Count > 0 ? " (" + numbered.Values.First() + " … " + numbered.Values.Last() + ")" : "") +
                                      " but transforms_" + split + ".json lists " + framePaths.Count + " frames; 3DGS renders every camera of the split in the file's order, so the n-th render belongs to the n-th frame only when the counts match.",
                    "Render from this very dataset (python render.py -m <model> with the model trained on it), or evaluate the split it was rendered from with --split.");
            var views = new List<RenderView>();
            for (var i = 0; i < framePaths.Count; i++) views.Add(new RenderView(i, framePaths[i], Path.Combine(folder, numbered[i])));
            return new RenderSet(RenderLayout.GaussianSplatting, folder, views, notes);
        }

        static RenderSet Nerfstudio(string root, string split, IReadOnlyList<string> framePaths)
        {
            var splitFolder = Directory.Exists(Path.Combine(root, split, "rgb")) ? Path.Combine(root, split) : root;
            var rgb = Path.Combine(splitFolder, "rgb");
            if (!Directory.Exists(rgb))
                throw Problem(Path.Combine(root, split, "rgb"), "does not exist: ns-render dataset writes <output-path>/" + split + "/rgb/<image name>.",
                    "Run ns-render dataset --load-config <config.yml> --split " + split + " --image-format png --rendered-output-names rgb raw-depth, and pass its --output-path.");
            var notes = new List<string>();
            var views = new List<RenderView>();
            var missing = new List<string>();
            var jpegs = 0;
            var depthFolder = Path.Combine(splitFolder, "raw-depth");
            var normalFolder = Path.Combine(splitFolder, "raw-normals");
            var hasDepth = Directory.Exists(depthFolder);
            var hasNormals = Directory.Exists(normalFolder);
            for (var i = 0; i < framePaths.Count; i++)
            {
                var name = BaseName(framePaths[i]);
                var png = Path.Combine(rgb, name + ".png");
                if (!File.Exists(png))
                {
                    if (File.Exists(Path.Combine(rgb, name + ".jpg"))) jpegs++;
                    missing.Add(name + ".png");
                    continue;
                }
                var view = new RenderView(i, framePaths[i], png);
                if (hasDepth)
                {
                    var depth = Path.Combine(depthFolder, name + ".npy.gz");
                    if (!File.Exists(depth)) throw Problem(depthFolder, "has no " + name + ".npy.gz for frame " + i + " (" + framePaths[i] + ").", "Render raw-depth for the whole split, or remove the raw-depth folder to score colour only.");
                    view.DepthPath = depth;
                    view.DepthFormat = RenderDataFormat.NpyGz;
                }
                if (hasNormals)
                {
                    var normals = Path.Combine(normalFolder, name + ".npy.gz");
                    if (!File.Exists(normals)) throw Problem(normalFolder, "has no " + name + ".npy.gz for frame " + i + " (" + framePaths[i] + ").", "Render raw-normals for the whole split, or remove the raw-normals folder.");
                    view.NormalPath = normals;
                    view.NormalFormat = RenderDataFormat.NpyGz;
                }
                views.Add(view);
            }
            if (jpegs > 0)
                throw Problem(rgb, "holds JPEG renders (" + jpegs + " of " + framePaths.Count + " frames): ns-render writes JPEG unless told otherwise, and JPEG's loss would be scored as the model's error.",
                    "Re-render with ns-render dataset … --image-format png.");
            if (missing.Count > 0)
                throw Problem(rgb, "has no render for " + missing.Count + " of the " + framePaths.Count + " frames of transforms_" + split + ".json (" + Describe(missing) + "); ns-render names each render after the frame's image.",
                    "Render the split of this very dataset: ns-render dataset --split " + split + " --image-format png.");
            var extra = Directory.GetFiles(rgb, "*.png").Select(Path.GetFileName).Except(framePaths.Select(p => BaseName(p) + ".png"), StringComparer.Ordinal).ToList();
            if (extra.Count > 0)
                throw Problem(rgb, "holds " + Describe(extra) + ", which no frame of transforms_" + split + ".json names.", "Render from this very dataset and split, or evaluate the split these renders come from with --split.");
            if (hasDepth) notes.Add("nerfstudio: depth from raw-depth/*.npy.gz (already divided by the dataparser scale, render.py line 845).");
            return new RenderSet(RenderLayout.Nerfstudio, rgb, views, notes);
        }

        static RenderSet ByName(string root, string split, IReadOnlyList<string> framePaths, RenderLayout layout)
        {
            var first = BaseName(framePaths.FirstOrDefault() ?? "");
            var folder = !File.Exists(Path.Combine(root, first + ".png")) && Directory.Exists(Path.Combine(root, split)) ? Path.Combine(root, split) : root;
            var views = new List<RenderView>();
            var missing = new List<string>();
            var jpegs = new List<string>();
            var expected = new HashSet<string>(StringComparer.Ordinal);
            for (var i = 0; i < framePaths.Count; i++)
            {
                var name = BaseName(framePaths[i]);
                expected.Add(name + ".png");
                var png = Path.Combine(folder, name + ".png");
                if (!File.Exists(png))
                {
                    var jpeg = new[] { ".jpg", ".jpeg" }.Select(e => name + e).FirstOrDefault(n => File.Exists(Path.Combine(folder, n)));
                    if (jpeg != null) jpegs.Add(jpeg);
                    missing.Add(name + ".png");
                    continue;
                }
                var view = new RenderView(i, framePaths[i], png);
                if (layout == RenderLayout.Plain)
                {
                    var depthName = name + DatasetLayout.Suffix(DatasetFileKind.DepthPng);
                    var normalName = name + DatasetLayout.Suffix(DatasetFileKind.NormalPng);
                    expected.Add(depthName);
                    expected.Add(normalName);
                    if (File.Exists(Path.Combine(folder, depthName))) { view.DepthPath = Path.Combine(folder, depthName); view.DepthFormat = RenderDataFormat.PluginPng; }
                    if (File.Exists(Path.Combine(folder, normalName))) { view.NormalPath = Path.Combine(folder, normalName); view.NormalFormat = RenderDataFormat.PluginPng; }
                }
                views.Add(view);
            }
            var source = layout == RenderLayout.InstantNgp ? "instant-ngp names each screenshot after the frame's file_path (scripts/run.py line 343)" : "a plain folder names each render r_<i>.png after the frame's file_path";
            // JPEG renders are found and named, not reported as missing (issue 33): their loss would be scored as the model's error.
            if (jpegs.Count > 0)
                throw Problem(folder, "holds JPEG renders where the PNGs should be (" + Describe(jpegs) + ": " + jpegs.Count + " of " + framePaths.Count +
                                      " frames); evaluate reads PNG, and JPEG's loss would be scored as the model's error.",
                    "Render the split again as PNG (converting a JPEG to PNG keeps its loss)" +
                    (layout == RenderLayout.InstantNgp ? ": instant-ngp's run.py writes each screenshot with the extension of the frame's file_path, so use the dataset's transforms_" + split + ".json, whose file_path has none." : "."));
            if (missing.Count > 0)
                throw Problem(folder, "has no render for " + missing.Count + " of the " + framePaths.Count + " frames of transforms_" + split + ".json (" + Describe(missing) + "); " + source + ".",
                    layout == RenderLayout.InstantNgp
                        ? "Render every frame: python scripts/run.py --load_snapshot <snapshot> --screenshot_transforms <dataset>/transforms_" + split + ".json --screenshot_dir <folder>."
                        : "Write one r_<i>.png per frame of the split, named as the frame's file_path.");
            var extra = Directory.GetFiles(folder, "*.png").Select(Path.GetFileName).Where(n => !expected.Contains(n)).ToList();
            if (extra.Count > 0)
                throw Problem(folder, "holds " + Describe(extra) + ", which no frame of transforms_" + split + ".json names (" + source + ").",
                    "Evaluate the split these renders come from with --split, or keep only this split's renders in the folder.");
            if (views.Any(v => v.DepthPath != null) && views.Any(v => v.DepthPath == null))
                throw Problem(folder, "has depth renders for some frames only (" + views.Count(v => v.DepthPath != null) + " of " + views.Count + ").", "Write r_<i>_depth_0000.png for every frame, or for none.");
            if (views.Any(v => v.NormalPath != null) && views.Any(v => v.NormalPath == null))
                throw Problem(folder, "has normal renders for some frames only (" + views.Count(v => v.NormalPath != null) + " of " + views.Count + ").", "Write r_<i>_normal_0000.png for every frame, or for none.");
            return new RenderSet(layout, folder, views, new List<string>());
        }

        /// <summary>Up to three of <paramref name="names"/> in reading order (<see cref="FileNameOrder"/>), then how many more.</summary>
        internal static string Describe(List<string> names)
        {
            var sorted = names.OrderBy(n => n, FileNameOrder.Instance).ToList();
            return sorted.Count <= 3 ? string.Join(", ", sorted) : string.Join(", ", sorted.Take(3)) + " and " + (sorted.Count - 3) + " more";
        }

        internal static InvalidParameterException Problem(string path, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem("--renders", path, reason, fix) });
    }
}
