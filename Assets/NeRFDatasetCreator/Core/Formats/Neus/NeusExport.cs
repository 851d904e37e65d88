using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to neus</c>: every frame of every split as NeuS (and IDR's layout) reads a case: <c>cameras_sphere.npz</c>
    /// with <c>world_mat_i</c> and <c>scale_mat_i</c> (<see cref="Neus"/>), <c>image/000.png</c> … as RGB over the
    /// protocol background (<c>cv.imread</c> drops alpha), <c>mask/000.png</c> … (0 or 255), and <c>splits.json</c>
    /// saying which image was in which split (NeuS trains on every image it finds).
    /// </summary>
    public static class NeusExport
    {
        public static ConversionResult Write(ExportScene scene, string outDir, List<ValidationProblem> warnings, StagedOutput staged)
        {
            const string target = "neus";
            InvalidParameterException.ThrowIfAny(Llff.LensRefusal(scene.Lens, target));
            var sphere = TargetSphere(scene.RootDirectory, warnings);
            var frames = scene.Frames;
            outDir = Path.GetFullPath(outDir);
            var cameras = Path.Combine(outDir, Neus.CamerasFileName);
            var splitsFile = Path.Combine(outDir, SplitsRecord.FileName);
            var images = Path.Combine(outDir, Neus.ImageFolder);
            var masks = Path.Combine(outDir, Neus.MaskFolder);
            foreach (var path in new[] { cameras, splitsFile, images, masks }) DatasetConverter.EnsureAbsent(path);

            var inside = frames.Count(f => Vector3d.Distance(f.Centre, sphere.Centre) <= sphere.Radius);
            if (inside > 0)
                warnings.Add(new ValidationProblem("target", inside + " cameras",
                    "are inside the target's bounding sphere, and NeuS samples each ray from 1 before to 1 after its closest approach to the unit sphere's centre (models/dataset.py near_far_from_sphere), assuming cameras outside it.",
                    "Capture from farther away than the target's bounding radius."));
            var background = ProtocolBackground.For(scene.RootDirectory);
            var scale = Neus.ScaleMat(sphere.Centre, sphere.Radius);
            var arrays = new List<KeyValuePair<string, byte[]>>();
            var written = new List<string>();
            var unmasked = 0;
            var names = frames.Select((f, i) => Neus.FileName(i, frames.Count)).ToList();
            for (var i = 0; i < frames.Count; i++)
            {
                var frame = frames[i];
                var image = ExportRgb.Decode(Path.Combine(scene.RootDirectory, frame.ImagePath), frame.ImagePath);
                var rgbPath = Path.Combine(images, names[i]);
                staged.WriteNewBytes(rgbPath, PngWriter.Encode(ExportRgb.Rgb(image, (background.R, background.G, background.B)), image.Width, image.Height, PngPixelFormat.Rgb8));
                var maskPath = Path.Combine(masks, names[i]);
                var mask = Mask(scene.RootDirectory, frame, image, ref unmasked);
                staged.WriteNewBytes(maskPath, PngWriter.Encode(mask, image.Width, image.Height, PngPixelFormat.Gray8));
                written.Add(rgbPath);
                written.Add(maskPath);
                arrays.Add(new KeyValuePair<string, byte[]>("world_mat_" + i, Matrix(Neus.WorldMat(frame.CameraToWorld, scene.Intrinsics))));
                arrays.Add(new KeyValuePair<string, byte[]>("scale_mat_" + i, Matrix(scale)));
            }
            if (unmasked > 0)
                warnings.Add(new ValidationProblem(Neus.MaskFolder, unmasked + " images",
                    "have neither a mask image nor alpha, so their masks are all 255 (everything is the object).",
                    "Train with NeuS's confs/womask.conf, or capture with masks or a transparent background."));
            staged.WriteNewBytes(cameras, NumpyFiles.Npz(arrays));
            staged.WriteNewText(splitsFile, SplitsRecord.Text(frames, names, background.Name));
            written.Add(cameras);
            written.Add(splitsFile);
            if (frames.Any(f => f.Split != "train"))
                warnings.Add(new ValidationProblem(SplitsRecord.FileName, frames.Count(f => f.Split != "train") + " val and test views",
                    "are exported with the train views: NeuS trains on every image in image/ and has no test split; splits.json lists which were which.",
                    "To hold them out, train on a copy without them (NeuS's images_to_pick in newer versions, or delete their image/mask files and renumber)."));
            return new ConversionResult(outDir, cameras, written, warnings, new[]
            {
                "copy " + outDir + " to NeuS/public_data/<case>/, then: python exp_runner.py --mode train --conf ./confs/wmask.conf --case <case>",
            });
        }

        /// <summary>The target's bounding sphere in the output frame, from dataset_config.json; refused when the dataset does not record it.</summary>
        static (Vector3d Centre, double Radius) TargetSphere(string root, List<ValidationProblem> warnings)
        {
            var config = DatasetConfig.Read(root).ThrowIfUnreadable().Config;
            var sphere = config == null ? null : DatasetTargetReach.Sphere(config.Json, warnings);
            if (sphere == null || !(sphere.Value.Radius > 0))
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(DatasetLayout.ConfigFileName + ": target", sphere == null ? "missing" : "radius 0",
                        "is the target's bounding sphere, which scale_mat_i maps onto NeuS's unit sphere (the region it reconstructs); this dataset does not record one.",
                        "Capture the dataset with this plugin's current version, with a target that has renderers."),
                });
            return sphere.Value;
        }

        /// <summary>The frame's mask: its mask image, else its alpha, else all 255 (counted).</summary>
        static byte[] Mask(string root, ExportFrame frame, PngImage image, ref int unmasked)
        {
            var pixels = image.Width * image.Height;
            if (frame.MaskPath != null)
            {
                var mask = PngReader.Read(Path.Combine(root, frame.MaskPath));
                if (mask.BitDepth != 8 || mask.ColorType != PngInfo.ColorTypeGray || mask.Width != image.Width || mask.Height != image.Height)
                    throw new InvalidParameterException(new[]
                    {
                        new ValidationProblem("mask_path", frame.MaskPath, "is not an 8-bit grey PNG of the image's size (" + image.Width + " × " + image.Height + ").", "Re-capture the masks with this plugin."),
                    });
                return Neus.Mask(mask.Samples, 1, 0, pixels);
            }
            if (image.ColorType == PngInfo.ColorTypeRgba) return Neus.Mask(image.Samples, 4, 3, pixels);
            unmasked++;
            var all = new byte[pixels];
            for (var p = 0; p < pixels; p++) all[p] = 255;
            return all;
        }

        static byte[] Matrix(Matrix4x4d m)
        {
            var values = new double[16];
            for (var r = 0; r < 4; r++) for (var c = 0; c < 4; c++) values[4 * r + c] = m[r, c];
            return NumpyFiles.Float64Matrix(values, 4, 4);
        }
    }
}
