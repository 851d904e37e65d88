using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset demo &lt;dir&gt; --renders-for &lt;demo dataset&gt;</c>: a STAND-IN for a trained model's renders of a demo
    /// dataset's test split, so that <c>nerf-dataset evaluate</c> and its report.html can be tried without a GPU. Each
    /// test view is ray-traced from the demo's own scene at the written pose, deliberately worse than the dataset's image
    /// — one sample per pixel (jagged edges, where the dataset has 2×2), a 3×3 blur and a little noise — and composited
    /// on white, as a model trained with a white background renders. Written as <c>r_&lt;i&gt;.png</c> (evaluate's plain
    /// layout) beside <see cref="NoteFileName"/>, which says what they are. They score high (they are the same scene)
    /// but not perfectly, which is what a report of a real model looks like.
    /// </summary>
    public static class DemoRenders
    {
        /// <summary>The note beside the renders, saying they are a stand-in and not a model's.</summary>
        public const string NoteFileName = "STAND-IN-RENDERS.txt";

        public const string Split = "test";

        /// <summary>The blur's centre weight (the 8 neighbours share the rest) and the noise's amplitude in 8-bit levels.</summary>
        const double CentreWeight = 0.6;
        const int NoiseLevels = 3;

        /// <summary>
        /// Why stand-in renders of <paramref name="datasetFolder"/> cannot be written into <paramref name="rendersFolder"/>
        /// (empty when they can): the dataset must be a demo (its scene is the demo's), the folder new or empty.
        /// </summary>
        public static IReadOnlyList<ValidationProblem> Check(string datasetFolder, string rendersFolder)
        {
            var problems = new List<ValidationProblem>();
            var config = Directory.Exists(datasetFolder) ? DatasetConfig.Read(datasetFolder).Config : null;
            if (!Directory.Exists(datasetFolder))
                problems.Add(new ValidationProblem("--renders-for", datasetFolder ?? "", "is not an existing folder.", "Name a folder nerf-dataset demo wrote, e.g. --renders-for demo/lego."));
            else if (config == null || !config.IsThisPlugin || (string)config.Settings?["name"] != DemoDataset.SettingsName)
                problems.Add(new ValidationProblem("--renders-for", Path.GetFullPath(datasetFolder),
                    "is not a dataset nerf-dataset demo wrote; stand-in renders are traced from the demo's own scene, so they exist only for a demo.",
                    "Name a folder nerf-dataset demo wrote, or evaluate a real model's renders (Documentation~/evaluate.md)."));
            else if (!File.Exists(DatasetFolder.SplitPath(datasetFolder, Split)))
                problems.Add(new ValidationProblem("--renders-for", Path.GetFullPath(datasetFolder), "has no " + DatasetLayout.TransformsFileName(Split) + ".", "Write the demo again with nerf-dataset demo."));
            var full = Path.GetFullPath(rendersFolder);
            if (File.Exists(full)) problems.Add(new ValidationProblem("folder", full, "is an existing file, not a folder.", "Name a new folder for the renders, e.g. demo/lego-renders."));
            else if (Directory.Exists(full) && Directory.EnumerateFileSystemEntries(full).Any())
                problems.Add(new ValidationProblem("folder", full, "is not empty; stand-in renders go only into a new or empty folder, so nothing is overwritten.",
                    "Name a new folder for the renders, or move that one away."));
            return problems;
        }

        /// <summary>Writes the stand-in renders; returns how many. Refused (nothing written) with <see cref="InvalidParameterException"/>.</summary>
        public static int Write(string datasetFolder, string rendersFolder)
        {
            var problems = Check(datasetFolder, rendersFolder);
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            var split = DatasetFolder.ReadSplit(datasetFolder, Split, DatasetReadMode.Strict);
            var normalisation = split.Has(BlenderTransformsWriter.SceneNormalisationKey)
                ? SceneNormalisation.FromJson(split.Value(BlenderTransformsWriter.SceneNormalisationKey))
                : SceneNormalisation.Identity;
            int width = split.W ?? 0, height = split.H ?? 0;
            if (width <= 0 || height <= 0 || split.CameraAngleX == null)
                throw new InvalidParameterException(new[] { new ValidationProblem(DatasetLayout.TransformsFileName(Split), "w, h, camera_angle_x", "are missing.", "Write the demo again with nerf-dataset demo.") });
            var intrinsics = CameraIntrinsics.FromVerticalFov(CameraIntrinsics.VerticalFovDegreesFromHorizontal(split.CameraAngleX.Value, width, height), width, height);
            var full = Path.GetFullPath(rendersFolder);
            Directory.CreateDirectory(full);
            var options = new AnalyticDataset.Options { Look = AnalyticLook.Demo };
            var scenes = new Dictionary<double, AnalyticScene>();
            var written = 0;
            foreach (var frame in split.Frames)
            {
                if (frame.TransformMatrix == null) continue;
                var time = frame.Time.Time ?? 0;
                if (!scenes.TryGetValue(time, out var scene)) scenes[time] = scene = AnalyticScene.Layout(normalisation, AnalyticDataset.Centre, time, AnalyticLook.Demo);
                var rays = AnalyticDataset.Rays(frame.TransformMatrix.Value, intrinsics, split.Lens);
                var raw = AnalyticDataset.Render(scene, rays, width, height, options, normalisation.Scale, 1);
                var rgb = Imperfect(raw, width, height, new Random(1000 + frame.Index));
                File.WriteAllBytes(Path.Combine(full, "r_" + frame.Index + ".png"), PngWriter.Encode(rgb, width, height, PngPixelFormat.Rgb8));
                written++;
            }
            File.WriteAllText(Path.Combine(full, NoteFileName),
                "STAND-IN RENDERS, not a trained model's.\n" +
                "nerf-dataset demo --renders-for " + Path.GetFullPath(datasetFolder) + " traced these " + written + " views of the demo's " + Split + " split\n" +
                "from its own scene, deliberately worse than the dataset's images (1 sample per pixel, a 3x3 blur, noise of up to\n" +
                NoiseLevels + " levels), so that nerf-dataset evaluate and its report.html can be tried without training.\n" +
                "Evaluate a real model's renders the same way (Documentation~/evaluate.md).\n");
            return written;
        }

        /// <summary>The render over white as 8-bit sRGB, top row first, blurred 3×3 and with seeded noise.</summary>
        static byte[] Imperfect(RawFrame frame, int width, int height, Random noise)
        {
            var linear = new double[width * height * 3];
            for (var y = 0; y < height; y++)
                for (var x = 0; x < width; x++)
                {
                    var source = ((height - 1 - y) * width + x) * 4; // readbacks are bottom row first
                    for (var c = 0; c < 3; c++) linear[(y * width + x) * 3 + c] = HalfFloat.ToFloat(frame.ColorOverWhite[source + c]);
                }
            var rgb = new byte[width * height * 3];
            for (var y = 0; y < height; y++)
                for (var x = 0; x < width; x++)
                    for (var c = 0; c < 3; c++)
                    {
                        double sum = 0, weight = 0;
                        for (var dy = -1; dy <= 1; dy++)
                            for (var dx = -1; dx <= 1; dx++)
                            {
                                int xx = x + dx, yy = y + dy;
                                if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
                                var w = dx == 0 && dy == 0 ? CentreWeight : (1 - CentreWeight) / 8;
                                sum += w * linear[(yy * width + xx) * 3 + c];
                                weight += w;
                            }
                        var value = Srgb.EncodeByteExact(Math.Max(0, Math.Min(1, sum / weight))) + noise.Next(-NoiseLevels, NoiseLevels + 1);
                        rgb[(y * width + x) * 3 + c] = (byte)Math.Max(0, Math.Min(255, value));
                    }
            return rgb;
        }
    }
}
