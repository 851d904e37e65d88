using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset convert d --to multiscale</c>: two layouts of every image at reduced scales, each in its own folder
    /// (Mip-Splatting takes a folder with <c>sparse/</c> for COLMAP before it looks for <c>metadata.json</c>, so they
    /// cannot share one):
    /// <list type="bullet">
    /// <item><c>colmap/</c>: <see cref="DatasetConverter"/>'s COLMAP model with <c>images/</c> and <c>images_2/4/8/</c> under
    /// the same file names (gsplat pairs the folders by sorted position and divides K by the factor), RGB composited over
    /// the dataset's protocol background (<see cref="ProtocolBackground"/>): gsplat drops alpha.</item>
    /// <item><c>mipnerf/</c>: mip-NeRF's multi-scale Blender layout (<see cref="MipNerfMultiscale"/>), RGBA: mip-NeRF,
    /// Mip-Splatting and Tri-MipRF composite alpha themselves.</item>
    /// </list>
    /// Every reduced level is a premultiplied box filter of the full image (<see cref="PremultipliedBox"/>), not of the
    /// level above, so each pixel is rounded once. Depth, normals and masks are not written at reduced scales: none of
    /// these readers takes them, and an averaged depth across a silhouette would be a surface that does not exist; the
    /// RGBA levels' alpha is the box-filtered coverage.
    /// </summary>
    public static class MultiscaleExport
    {
        public const string FolderName = "multiscale";
        public const string ColmapFolder = "colmap";

        /// <summary>gsplat's <c>images_&lt;factor&gt;</c> folders (examples/datasets/colmap.py; its default data_factor is 4).</summary>
        public static readonly int[] ColmapFactors = { 2, 4, 8 };

        public static string ColmapImagesFolder(int factor) => factor == 1 ? ColmapTextWriter.ImagesFolder : ColmapTextWriter.ImagesFolder + "_" + factor;

        public static ConversionResult Write(ExportScene scene, string outDir, IReadOnlyList<CloudPoint> points, List<ValidationProblem> warnings, StagedOutput staged)
        {
            outDir = Path.GetFullPath(outDir);
            var k = scene.Intrinsics;
            if (scene.Lens != null)
                throw Refuse("--to", "multiscale",
                    "cannot hold lens distortion: mip-NeRF's metadata.json gives each image a pinhole pix2cam only, and this dataset's images were taken through " + scene.Lens.Describe() + ".",
                    "Undistort the images to a pinhole first, or convert to nerfstudio or colmap, which carry the lens.");
            const int smallest = 1 << (MipNerfMultiscale.Levels - 1);
            if (k.Width < smallest || k.Height < smallest)
                throw Refuse("w, h", k.Width + "×" + k.Height, "is smaller than 8 pixels on a side, so the 1/8 level would have no pixel.", "Capture at least 8×8 pixels.");

            var colmapDir = Path.Combine(outDir, ColmapFolder);
            var mipDir = Path.Combine(outDir, MipNerfMultiscale.FolderName);
            var names = ColmapTextWriter.ImageNames(scene.Frames);
            var metadata = Path.Combine(mipDir, MipNerfMultiscale.MetadataFileName);
            var reduced = new List<string>();
            var levels = new List<string>();
            for (var i = 0; i < scene.Frames.Count; i++)
            {
                reduced.AddRange(ColmapFactors.Select(f => Path.Combine(colmapDir, ColmapImagesFolder(f), names[i])));
                for (var level = 0; level < MipNerfMultiscale.Levels; level++)
                    levels.Add(Path.Combine(mipDir, MipNerfMultiscale.FilePath(scene.Frames[i].Split, names[i], level)));
            }
            foreach (var path in reduced.Concat(levels).Concat(new[] { metadata })) DatasetConverter.EnsureAbsent(path);

            var background = ProtocolBackground.For(scene.RootDirectory);
            // Each image is read once: the COLMAP writer asks for images/<name> and every level is written from the same pixels.
            var colmap = DatasetConverter.ToColmap(scene, colmapDir, points, warnings, false, ColmapOptions.Default, staged, writeImage: (index, destination) =>
            {
                var frame = scene.Frames[index];
                var image = Decode(scene.RootDirectory, frame.ImagePath, k);
                foreach (var factor in new[] { 1 }.Concat(ColmapFactors))
                {
                    var rgb = PremultipliedBox.RgbOver(image.Samples, image.Width, image.Height, image.Channels, factor, background.R, background.G, background.B);
                    var path = factor == 1 ? destination : Path.Combine(colmapDir, ColmapImagesFolder(factor), names[index]);
                    staged.WriteNewBytes(path, PngWriter.Encode(rgb, PremultipliedBox.Reduced(image.Width, factor), PremultipliedBox.Reduced(image.Height, factor), PngPixelFormat.Rgb8));
                }
                for (var level = 0; level < MipNerfMultiscale.Levels; level++)
                {
                    var factor = 1 << level;
                    var rgba = PremultipliedBox.Rgba(image.Samples, image.Width, image.Height, image.Channels, factor);
                    staged.WriteNewBytes(Path.Combine(mipDir, MipNerfMultiscale.FilePath(frame.Split, names[index], level)),
                        PngWriter.Encode(rgba, PremultipliedBox.Reduced(image.Width, factor), PremultipliedBox.Reduced(image.Height, factor), PngPixelFormat.Rgba8));
                }
            });

            // gsplat's own hold-out, not 3DGS's, is what a user of colmap/ meets (examples/datasets/colmap.py Dataset: test_every 8).
            var noSplits = warnings.FindIndex(w => w.Reason.StartsWith("COLMAP has no splits", System.StringComparison.Ordinal));
            if (noSplits >= 0)
                warnings[noSplits] = new ValidationProblem(warnings[noSplits].Field, warnings[noSplits].Value,
                    "COLMAP has no splits: colmap/ lists train, val and test views alike, and gsplat holds out every 8th image in name order (test_every 8), not the dataset's test views.",
                    "For the dataset's own splits, train on mipnerf/ (metadata.json keeps train, val and test apart).");
            var reach = scene.TargetReach;
            if (reach == null)
                warnings.Add(new ValidationProblem("near, far", "2, 6",
                    "are nerf_synthetic's bounds (what mip-NeRF's converter writes): the dataset does not record how far its target reaches.",
                    "Capture with this plugin (dataset_config.json records the reach), or edit near/far in metadata.json."));
            var json = new JObject();
            foreach (var split in MipNerfMultiscale.Splits)
            {
                var frames = scene.Frames.Select((f, i) => (FlatName: names[i], Frame: f)).Where(p => p.Frame.Split == split).ToList();
                json[split] = MipNerfMultiscale.Split(frames, split, k, f => reach.HasValue ? MipNerfMultiscale.Bounds(f.CameraToWorld, Vector3d.Zero, reach.Value) : (2.0, 6.0));
            }
            staged.WriteNewText(metadata, json.ToString() + "\n");

            if (k.Width % smallest != 0 || k.Height % smallest != 0)
                warnings.Add(new ValidationProblem("w, h", k.Width + "×" + k.Height,
                    "is not divisible by 8: each reduced level drops the last W mod f columns and H mod f rows, so its pixels are whole f×f blocks and the intrinsics scale by exactly 1/f (pix2cam holds them). Mip-Splatting reads only focal and puts the principal point at the level's centre, up to " +
                    (System.Math.Max(k.Width % smallest, k.Height % smallest) / 2.0 / smallest).ToString(System.Globalization.CultureInfo.InvariantCulture) + " px off at 1/8.",
                    "Capture at a size divisible by 8 for Mip-Splatting."));
            else if (k.FlX != k.FlY || k.Cx != k.Width / 2.0 || k.Cy != k.Height / 2.0)
                warnings.Add(new ValidationProblem("focal", k.FlX.ToString(System.Globalization.CultureInfo.InvariantCulture),
                    "is the only intrinsic Mip-Splatting reads (square pixels, centred principal point); this camera has fx " + k.FlX + ", fy " + k.FlY + ", cx " + k.Cx + ", cy " + k.Cy + ". pix2cam holds them exactly for mip-NeRF and Tri-MipRF.",
                    "Use mip-NeRF or Tri-MipRF, or capture with a centred square-pixel camera for Mip-Splatting."));

            var written = new List<string>(colmap.WrittenFiles);
            written.AddRange(reduced);
            written.AddRange(levels);
            written.Add(metadata);
            return new ConversionResult(outDir, metadata, written, warnings, Commands(colmapDir, mipDir, background.R == 255 && background.G == 255 && background.B == 255));
        }

        /// <summary>gsplat at data_factor 4 (its default) on colmap/, and the three mip-NeRF-layout trainers on mipnerf/.</summary>
        public static IReadOnlyList<string> Commands(string colmapDir, string mipDir, bool white)
        {
            return new[]
            {
                "python simple_trainer.py default --data_dir " + Quote(colmapDir) + " --data_factor 4 --result_dir " + Quote("results/" + ExportPaths.RunName(Path.GetDirectoryName(colmapDir), FolderName)) + "   (gsplat examples/; --data_factor 1, 2, 4 or 8)",
                "python train.py -s " + Quote(mipDir) + " -m " + Quote("output/" + ExportPaths.RunName(Path.GetDirectoryName(mipDir), FolderName)) + " --eval" + (white ? " --white_background" : "") + "   (Mip-Splatting: trains on _d0, tests every scale; --load_allres trains on all)",
                "python -m train --data_dir=" + Quote(mipDir) + " --train_dir=" + Quote("train/" + ExportPaths.RunName(Path.GetDirectoryName(mipDir), FolderName)) + " --gin_file=configs/multiblender.gin   (mip-NeRF)",
            };
        }

        static PngImage Decode(string root, string relative, CameraIntrinsics k)
        {
            PngImage image;
            try { image = PngReader.Read(Path.Combine(root, relative)); }
            catch (InvalidDataException e) { throw Refuse("file_path", relative, e.Message, "Re-capture the dataset with this plugin, or re-save the image as an 8-bit RGB or RGBA PNG."); }
            if (image.BitDepth != 8 || (image.Channels != 3 && image.Channels != 4))
                throw Refuse("file_path", relative, "is a " + image.BitDepth + "-bit PNG with " + image.Channels + " channel(s); the multi-scale levels are filtered from 8-bit RGB or RGBA.", "Re-save the image as an 8-bit RGB or RGBA PNG.");
            if (image.Width != k.Width || image.Height != k.Height)
                throw Refuse("file_path", relative, "is " + image.Width + "×" + image.Height + " but the camera is " + k.Width + "×" + k.Height + ".", "Export images of the camera's size.");
            return image;
        }

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
