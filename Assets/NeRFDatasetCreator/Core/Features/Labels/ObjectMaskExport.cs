using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset convert d --to nerfstudio --object &lt;name|id&gt;</c>: a nerfstudio <c>transforms.json</c> whose
    /// <c>mask_path</c> per frame names a mask of that one object, so that a trainer with mask support learns it alone.
    /// Each mask is 8-bit grey, 255 where the frame's instance map holds the object's id and 0 elsewhere: nerfstudio
    /// reads one channel and keeps the pixels that are not 0 (<c>get_image_mask_tensor_from_path</c>, ….bool(); pixels
    /// with mask 0 are never sampled or are zeroed in the loss — Documentation~/maintainers/labels-exports.md). The
    /// masks go to <c>masks/&lt;split&gt;/&lt;image&gt;.png</c> in the output, by default <c>&lt;dir&gt;/object_&lt;id&gt;/</c>; the
    /// images stay where they are and are named relative to it.
    /// </summary>
    public static class ObjectMaskExport
    {
        public const string MaskFolder = "masks";

        /// <summary>The default output of <c>--object</c>: <c>&lt;dir&gt;/object_&lt;id&gt;</c>.</summary>
        public static string DefaultFolder(string root, int instanceId) =>
            Path.GetFullPath(Path.Combine(root, "object_" + instanceId.ToString(CultureInfo.InvariantCulture)));

        /// <summary>The mask of one object in an instance map: 255 where the map holds <paramref name="instanceId"/>, else 0.</summary>
        public static byte[] Mask(ushort[] instanceMap, int instanceId)
        {
            var mask = new byte[instanceMap.Length];
            for (var i = 0; i < mask.Length; i++) mask[i] = instanceMap[i] == instanceId ? (byte)255 : (byte)0;
            return mask;
        }

        /// <summary>
        /// Writes the masks of <paramref name="label"/> into <paramref name="outDir"/> and returns the scene with every frame's
        /// <see cref="ExportFrame.MaskPath"/> set to its mask (relative to the dataset root), ready for the nerfstudio writer.
        /// </summary>
        public static ExportScene WriteMasks(ExportScene scene, LabelledDataset labelled, InstanceLabel label, string outDir,
            List<ValidationProblem> warnings, StagedOutput staged, List<string> written)
        {
            outDir = Path.GetFullPath(outDir);
            var paths = scene.Frames.Select(f => Path.Combine(outDir, MaskFolder, MaskName(f.ImagePath))).ToList();
            foreach (var dup in paths.GroupBy(p => p).Where(g => g.Count() > 1))
                throw new InvalidParameterException(new[] { new ValidationProblem("file_path", dup.Key, "is the mask of " + dup.Count() + " images.", "Give every image a distinct path.") });
            foreach (var path in paths) DatasetConverter.EnsureAbsent(path);
            var maps = new List<byte[]>();
            var empty = new List<string>();
            for (var i = 0; i < scene.Frames.Count; i++)
            {
                var mask = Mask(labelled.ReadInstanceMap(scene, i), label.Id);
                if (mask.All(v => v == 0)) empty.Add(scene.Frames[i].ImagePath);
                maps.Add(mask);
            }
            if (empty.Count == scene.Frames.Count)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(ObjectSelection.Option, ObjectSelection.Describe(label), "covers no pixel of any view: every mask would be empty and nothing could be trained.",
                        "Pick an object the cameras see (labels_preview_<split>.png shows them), or capture views of it."),
                });
            if (empty.Count > 0)
                warnings.Add(new ValidationProblem(ObjectSelection.Option, ObjectSelection.Describe(label),
                    "is not visible in " + empty.Count + " of " + scene.Frames.Count + " views (e.g. " + empty[0] + "); their masks are empty, so those views teach nothing about it.",
                    "Nothing to do if the object is hidden there on purpose."));
            var frames = new List<ExportFrame>();
            for (var i = 0; i < scene.Frames.Count; i++)
            {
                staged.WriteNewBytes(paths[i], PngWriter.Encode(maps[i], scene.Intrinsics.Width, scene.Intrinsics.Height, PngPixelFormat.Gray8));
                written.Add(paths[i]);
                var f = scene.Frames[i];
                var rootRelative = Path.GetRelativePath(scene.RootDirectory, paths[i]).Replace('\\', '/');
                frames.Add(new ExportFrame(f.Split, f.ImagePath, f.CameraToWorld, f.DepthPath, rootRelative, f.Time, f.UnusableDepth));
            }
            return new ExportScene(scene.RootDirectory, scene.Intrinsics, frames, scene.PointCloudPath, scene.Normalisation, scene.DepthUnitScale,
                scene.DeclaredAabbScale, scene.TargetReach, scene.InsideOut, scene.Lens, scene.UnityFrame);
        }

        /// <summary><c>train/r_0.png</c> → <c>train/r_0.png</c> under <see cref="MaskFolder"/>: the image's own relative path (PNG).</summary>
        static string MaskName(string imagePath)
        {
            var normalised = ExportPaths.Normalise(imagePath);
            return Path.ChangeExtension(normalised, ".png");
        }
    }
}
