using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to llff</c>: every frame of every split as LLFF's loaders read a scene (bmild/nerf load_llff.py,
    /// NSFF, nerf-pytorch): <c>poses_bounds.npy</c> (N × 17 float64, <see cref="Llff.Row"/>) with each view's exact near
    /// and far from its depth map (<see cref="DepthBounds"/>), the images as <c>images/0000.png</c> … in the same order,
    /// RGB over the protocol background (load_llff.py:114 keeps <c>[..., :3]</c>), and <c>splits.json</c> saying which
    /// image was in which split (LLFF has no splits: run_nerf.py's <c>--llffhold 8</c> tests on every 8th image instead).
    /// </summary>
    public static class LlffExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            const string target = "llff";
            InvalidParameterException.ThrowIfAny(Llff.LensRefusal(scene.Lens, target), Llff.CameraRefusal(scene.Intrinsics, target));
            var frames = scene.Frames;
            var bounds = DepthBounds.Of(scene, frames, target, warnings);
            outDir = Path.GetFullPath(outDir);
            var posesFile = Path.Combine(outDir, Llff.PosesBoundsFileName);
            var splitsFile = Path.Combine(outDir, SplitsRecord.FileName);
            var images = Path.Combine(outDir, Llff.ImagesFolder);
            foreach (var path in new[] { posesFile, splitsFile, images }) DatasetConverter.EnsureAbsent(path);

            var k = scene.Intrinsics;
            var values = new double[frames.Count * 17];
            for (var i = 0; i < frames.Count; i++)
                System.Array.Copy(Llff.Row(frames[i].CameraToWorld, k.Height, k.Width, k.FlX, bounds[i].Near, bounds[i].Far), 0, values, 17 * i, 17);
            var background = ProtocolBackground.For(scene.RootDirectory);
            var written = new List<string>();
            var names = frames.Select((f, i) => Llff.ImageName(i, frames.Count)).ToList();
            for (var i = 0; i < frames.Count; i++)
            {
                var to = Path.Combine(images, names[i]);
                ExportRgb.Write(scene.RootDirectory, frames[i].ImagePath, to, (background.R, background.G, background.B), staged);
                written.Add(to);
            }
            staged.WriteNewBytes(posesFile, NumpyFiles.Float64Matrix(values, frames.Count, 17));
            staged.WriteNewText(splitsFile, SplitsRecord.Text(frames, names, background.Name));
            written.Add(posesFile);
            written.Add(splitsFile);
            warnings.Add(HoldOutWarning(frames, splitsFile));
            return new ConversionResult(outDir, posesFile, written, warnings, new[]
            {
                "nerf-pytorch: python run_nerf.py --dataset_type llff --datadir " + outDir + " --factor 1 --no_ndc --spherify --llffhold 8   (--factor 1 reads images_1/, which load_llff.py makes from images/ with ImageMagick's mogrify)",
            });
        }

        /// <summary>LLFF's hold-out convention is not the dataset's split: say which images each one tests on.</summary>
        static ValidationProblem HoldOutWarning(IReadOnlyList<ExportFrame> frames, string splitsFile) =>
            new ValidationProblem(Path.GetFileName(splitsFile), frames.Count(f => f.Split == "test") + " test views",
                "are exported with every other view: LLFF has no splits, and nerf-pytorch's --llffhold " + Llff.HoldEvery + " tests on images 0, " + Llff.HoldEvery + ", " + 2 * Llff.HoldEvery +
                " … (every " + Llff.HoldEvery + "th of the sorted list), not on the dataset's test split; splits.json lists the real one (i_test).",
                "For the dataset's own protocol, set i_test from splits.json in the trainer, or train on the Blender layout itself.");
    }
}
