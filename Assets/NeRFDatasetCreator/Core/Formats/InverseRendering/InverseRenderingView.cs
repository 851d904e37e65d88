using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One view of a dataset as the inverse-rendering exports (tensoir, gs-ir, r3dg) read it: its pose and image, and the
    /// files its frame keys name — normals, the material passes (<see cref="MaterialKeys"/>: the PNG path, the EXR truth
    /// beside it) and the relit images (<see cref="RelightingKeys.RelitPaths"/>). Only the keys are read, never a name
    /// guessed from the image's (contract38: "Read materials/relights through frame keys only").
    /// </summary>
    public sealed class InverseRenderingView
    {
        public string Split;

        /// <summary>The view's position in its split's transforms file (the loaders number folders by it).</summary>
        public int Index;

        /// <summary>The image's file name without extension (<c>r_7</c>).</summary>
        public string Stem;

        public Matrix4x4d CameraToWorld;
        public string ImagePath;
        public string NormalPath;
        public string HdrPath;

        /// <summary>The material passes' EXR truth (the key's PNG path with <c>.exr</c>), or null when the frame has no such key.</summary>
        public string AlbedoExr, MetallicExr, RoughnessExr;

        /// <summary>Each lighting condition's key (<c>sunset_090</c>, <c>olat-00</c>) → the view's PNG under it.</summary>
        public readonly SortedDictionary<string, string> Relit = new SortedDictionary<string, string>(StringComparer.Ordinal);

        /// <summary>The relit view's linear colour (<c>r_&lt;i&gt;_light_&lt;key&gt;_hdr.exr</c>), or null when there is none.</summary>
        public string RelitHdr(string key)
        {
            if (!Relit.TryGetValue(key, out var png)) return null;
            var exr = png.Substring(0, png.Length - Path.GetExtension(png).Length) + "_hdr.exr";
            return File.Exists(exr) ? exr : null;
        }

        /// <summary>The EXR truth of a material key's PNG path: the same path with <c>.exr</c> (contract38, per-view files).</summary>
        static string Exr(DatasetFrame frame, string key)
        {
            var file = frame.Named(key);
            if (file == null || file.FullPath == null) return null;
            return Path.ChangeExtension(file.FullPath, ".exr");
        }

        /// <summary>Reads every split the dataset has (train, val, test in that order), each view's files resolved from its keys.</summary>
        public static List<InverseRenderingView> Read(string root)
        {
            var views = new List<InverseRenderingView>();
            foreach (var split in DatasetSplits.Names)
            {
                if (!File.Exists(DatasetFolder.SplitPath(root, split))) continue;
                var file = DatasetFolder.ReadSplit(root, split, DatasetReadMode.Strict);
                foreach (var frame in file.Frames)
                {
                    if (frame.TransformMatrix == null || frame.Image == null)
                        throw new InvalidParameterException(new[] { new ValidationProblem(DatasetLayout.TransformsFileName(split), "frame " + frame.Index, "has no transform_matrix or file_path.", "Fix or re-capture the dataset.") });
                    var view = new InverseRenderingView
                    {
                        Split = split,
                        Index = file.Frames.IndexOf(frame),
                        Stem = Path.GetFileNameWithoutExtension(frame.Image.FullPath),
                        CameraToWorld = frame.TransformMatrix.Value,
                        ImagePath = frame.Image.FullPath,
                        NormalPath = frame.Named("normal_path")?.FullPath,
                        HdrPath = frame.Named(HdrKeys.HdrPath)?.FullPath,
                        AlbedoExr = Exr(frame, MaterialKeys.AlbedoPath),
                        MetallicExr = Exr(frame, MaterialKeys.MetallicPath),
                        RoughnessExr = Exr(frame, MaterialKeys.RoughnessPath),
                    };
                    if (frame.Json?[RelightingKeys.RelitPaths] is JObject relit)
                        foreach (var pair in relit)
                            if (pair.Value?.Type == JTokenType.String)
                            {
                                var resolved = DatasetFile.Resolve(root, RelightingKeys.RelitPaths + "." + pair.Key, (string)pair.Value, false);
                                if (resolved.FullPath != null) view.Relit[pair.Key] = resolved.FullPath;
                            }
                    views.Add(view);
                }
            }
            return views;
        }

        /// <summary>The camera_angle_x of a split (every loader here takes the focal from it).</summary>
        public static double CameraAngleX(string root, string split)
        {
            var file = DatasetFolder.ReadSplit(root, split, DatasetReadMode.Strict);
            if (file.CameraAngleX == null)
                throw new InvalidParameterException(new[] { new ValidationProblem("camera_angle_x", DatasetLayout.TransformsFileName(split), "is missing: TensoIR, NeRFactor, GS-IR and R3DG take the focal length from it.", "Capture with a pinhole camera.") });
            return file.CameraAngleX.Value;
        }
    }
}
