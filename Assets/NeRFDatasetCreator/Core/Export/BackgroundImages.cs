using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes an export's images composited over its <see cref="ExportBackground"/> with <see cref="AlphaCompositing"/>
    /// (straight alpha on the stored 8-bit sRGB values, nearest code), each image's alpha beside it as an 8-bit grey
    /// mask (255 opaque, 0 transparent) in <c>masks/</c>, and <c>backgrounds.json</c> with the rule and every image's colour.
    /// </summary>
    public static class BackgroundImages
    {
        public const string ImagesFolder = "images";
        public const string MasksFolder = "masks";
        public const string RecordFileName = "backgrounds.json";

        /// <summary>One image to write: the dataset image, where its composite and its mask go, and its dataset path (the record's key).</summary>
        public sealed class Item
        {
            public string Source;
            public string Image;
            public string Mask;
            public string DatasetPath;
        }

        /// <summary>Every destination (images, masks, the record), for the never-overwrite check before anything is written.</summary>
        public static IEnumerable<string> Destinations(IReadOnlyList<Item> items, string outDir) =>
            items.SelectMany(i => new[] { i.Image, i.Mask }).Concat(new[] { Path.Combine(outDir, RecordFileName) });

        /// <summary>Writes every item and the record; returns the files written. Images without alpha are written unchanged (one warning).</summary>
        public static IReadOnlyList<string> Write(IReadOnlyList<Item> items, ExportBackground background, string outDir, StagedOutput staged, List<ValidationProblem> warnings)
        {
            var written = new List<string>();
            var colours = new JObject();
            var opaque = new List<string>();
            foreach (var item in items)
            {
                var colour = background.ColourOf(item.DatasetPath);
                var png = Decode(item.Source, item.DatasetPath);
                var pixels = png.Width * png.Height;
                var rgb = new byte[pixels * 3];
                var mask = new byte[pixels];
                if (png.ColorType == PngInfo.ColorTypeRgba)
                {
                    AlphaCompositing.OverSolid(png.Samples, rgb, pixels, colour.R, colour.G, colour.B);
                    for (var i = 0; i < pixels; i++) mask[i] = png.Samples[4 * i + 3];
                }
                else
                {
                    // RGB: nothing to composite (every pixel opaque).
                    System.Buffer.BlockCopy(png.Samples, 0, rgb, 0, rgb.Length);
                    for (var i = 0; i < pixels; i++) mask[i] = 255;
                    opaque.Add(item.DatasetPath);
                }
                staged.WriteNewBytes(item.Image, PngWriter.Encode(rgb, png.Width, png.Height, PngPixelFormat.Rgb8));
                staged.WriteNewBytes(item.Mask, PngWriter.Encode(mask, png.Width, png.Height, PngPixelFormat.Gray8));
                written.Add(item.Image);
                written.Add(item.Mask);
                colours[ExportPaths.Normalise(item.DatasetPath)] = new JArray(colour.R, colour.G, colour.B);
            }
            if (opaque.Count > 0)
                warnings.Add(new ValidationProblem("--background", background.Name, opaque.Count + " of " + items.Count + " images (e.g. " + opaque[0] + ") have no alpha, so they were written unchanged and their masks are all opaque.",
                    "Nothing to do if the dataset was captured on a solid background; capture with a transparent background to composite."));
            var record = new JObject
            {
                ["background"] = background.Name,
                ["compositing"] = "straight alpha over the colour on the stored 8-bit sRGB values: out = floor((c*a + bg*(255 - a) + 127) / 255) per channel",
                ["masks"] = MasksFolder + "/: each image's alpha, 8-bit grey, 255 opaque",
            };
            if (background.FromProtocol) record["from"] = "the dataset's protocol background (--background protocol)";
            if (background.IsRandom)
            {
                record["seed"] = background.Seed;
                record["rule"] = ExportBackground.RandomRule;
            }
            record["images"] = colours;
            var path = Path.Combine(outDir, RecordFileName);
            staged.WriteNewText(path, record.ToString(Formatting.Indented) + "\n");
            written.Add(path);
            return written;
        }

        static PngImage Decode(string path, string shown)
        {
            try
            {
                var png = PngReader.Read(path);
                if (png.BitDepth != 8 || (png.ColorType != PngInfo.ColorTypeRgba && png.ColorType != PngInfo.ColorTypeRgb))
                    throw new InvalidDataException("is not an 8-bit RGB or RGBA PNG (bit depth " + png.BitDepth + ", colour type " + png.ColorType + ").");
                return png;
            }
            catch (InvalidDataException e)
            {
                throw new InvalidParameterException(new[] { new ValidationProblem("file_path", shown, e.Message, "--background composites the 8-bit RGBA PNGs this plugin captures; re-capture, or convert without --background.") });
            }
        }

        /// <summary>
        /// nerfstudio: writes the composites under <c>images/</c> and the masks under <c>masks/</c> of the export (each
        /// at its dataset path) and returns the scene whose frames name the composites. Their <c>mask_path</c> is left
        /// out on purpose: nerfstudio samples only pixels whose mask is not 0 (pixel_samplers.py) and splatfacto zeroes
        /// the rest of the loss, so naming the alpha would drop exactly the background pixels the composite supervises.
        /// </summary>
        public static ExportScene ForNerfstudio(ExportScene scene, ExportBackground background, string outDir, StagedOutput staged, List<ValidationProblem> warnings, List<string> written)
        {
            outDir = Path.GetFullPath(outDir);
            var items = scene.Frames.Select(f => new Item
            {
                Source = Path.Combine(scene.RootDirectory, f.ImagePath),
                Image = Path.Combine(outDir, ImagesFolder, Path.ChangeExtension(ExportPaths.Normalise(f.ImagePath), ".png")),
                Mask = Path.Combine(outDir, MasksFolder, Path.ChangeExtension(ExportPaths.Normalise(f.ImagePath), ".png")),
                DatasetPath = f.ImagePath,
            }).ToList();
            foreach (var path in Destinations(items, outDir)) DatasetConverter.EnsureAbsent(path);
            written.AddRange(Write(items, background, outDir, staged, warnings));
            var frames = scene.Frames.Select((f, i) =>
            {
                var image = Path.GetRelativePath(scene.RootDirectory, items[i].Image).Replace('\\', '/');
                return new ExportFrame(f.Split, image, f.CameraToWorld, f.DepthPath, null, f.Time, f.UnusableDepth);
            }).ToList();
            return new ExportScene(scene.RootDirectory, scene.Intrinsics, frames, scene.PointCloudPath, scene.Normalisation, scene.DepthUnitScale,
                scene.DeclaredAabbScale, scene.TargetReach, scene.InsideOut, scene.Lens);
        }

        /// <summary>The train commands with the background flag each trainer needs to render on the same colour.</summary>
        public static IReadOnlyList<string> Commands(IReadOnlyList<string> commands, ExportTarget target, ExportBackground background)
        {
            if (background.IsRandom) return commands;
            return commands.Select(c =>
            {
                // 3DGS: -w renders (and trains) on white, its default is black (arguments/__init__.py white_background).
                if (target == ExportTarget.Colmap && c.StartsWith("python train.py", System.StringComparison.Ordinal) && background.Name == "white")
                    return c.Replace(" --eval", " --eval -w");
                // nerfstudio: model options go before the dataparser (splatfacto's default is random, nerfacto's last_sample).
                if (target == ExportTarget.Nerfstudio && c.StartsWith("ns-train ", System.StringComparison.Ordinal) && (background.Name == "white" || background.Name == "black"))
                {
                    var space = c.IndexOf(' ', "ns-train ".Length);
                    return space < 0 ? c : c.Substring(0, space) + " --pipeline.model.background-color " + background.Name + c.Substring(space);
                }
                return c;
            }).ToList();
        }
    }
}
