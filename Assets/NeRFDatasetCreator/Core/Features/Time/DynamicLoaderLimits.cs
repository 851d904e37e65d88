using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the 4D trainers' own code cannot take, warned at plan time for the loaders listed in "Made for"
    /// (<c>loaders</c>): in a dynamic capture, <c>nerf</c> is D-NeRF (its <c>load_blender.py</c> is NeRF's Blender loader
    /// with <c>time</c>) and <c>3dgs</c> is 4DGaussians (3D Gaussian Splatting's code with a deformation field, reading the
    /// same layout). Each rule is from the loader's code (Documentation~/dynamic-capture.md, "What the loaders need"):
    /// <list type="bullet">
    /// <item>D-NeRF, albertpumarola/D-NeRF 2137203: <c>--half_res</c> resizes with <c>cv2.resize(img, (H, W))</c>
    /// (load_blender.py:137), but OpenCV's size is (width, height), so a non-square image does not fit its H × W slot
    /// and loading fails (D-NeRF's own configs set <c>half_res = True</c>). Its <c>--testskip</c> (command-line default 2,
    /// run_dnerf.py:570) thins train too, which breaks an even number of monocular train views; its configs set
    /// <c>testskip = 1</c>, so that is said in the docs rather than warned on every such capture.</item>
    /// <item>4DGaussians, hustvl/4DGaussians 843d5ac: every image is resized to 800 × 800 and the vertical field of view
    /// is taken from the horizontal one (scene/dataset_readers.py:288–289); without <c>fused.ply</c> it starts from 2000
    /// random points in ±1.3 about the origin (lines 327–333), which also bound its deformation grid
    /// (scene/__init__.py:77–83), and it renders its video on an orbit of radius 4 about the origin (line 226).</item>
    /// </list>
    /// </summary>
    public static class DynamicLoaderLimits
    {
        public const string Field = "loaders";

        public static IReadOnlyList<ValidationProblem> For(DatasetSettings settings)
        {
            var warnings = new List<ValidationProblem>();
            if (settings?.Time == null || settings.Time.Mode == TimeMode.Static) return warnings;
            var loaders = settings.Loaders;
            var square = settings.Width == settings.Height;
            var size = I(settings.Width) + " × " + I(settings.Height);

            if ((loaders & TargetLoaders.Nerf) != 0)
            {
                if (!square)
                    warnings.Add(new ValidationProblem(Field, "nerf (D-NeRF)",
                        "with " + size + " images: D-NeRF's --half_res resizes with cv2.resize(img, (H, W)) (load_blender.py:137), which OpenCV reads as (width, height), so a non-square image does not fit and loading fails.",
                        "Set half_res = False in the D-NeRF config (its configs/*.txt set True) and capture at the size to train at, or capture square images."));
            }

            if ((loaders & TargetLoaders.GaussianSplatting) != 0)
            {
                if (!square)
                    warnings.Add(new ValidationProblem(Field, "3dgs (4DGaussians)",
                        "with " + size + " images: 4DGaussians resizes every image to 800 × 800 and sets the vertical field of view equal to the horizontal one (scene/dataset_readers.py:288–289), so non-square images train squashed, with a wrong vertical field of view.",
                        "Capture square images (e.g. 800 × 800) for 4DGaussians."));
                var offOrigin = new List<string>();
                foreach (var split in DatasetSplits.All)
                {
                    var source = settings.Split(split).Source;
                    if (settings.Split(split).Count > 0 && source != null && !source.IsFormation)
                        offOrigin.Add("splits." + DatasetSplits.Name(split) + ".source (" + CameraSourceName(source.Kind) + ")");
                }
                if (settings.Normalisation == NormalisationMode.None) offOrigin.Add("normalisation \"none\"");
                if (offOrigin.Count > 0)
                    warnings.Add(new ValidationProblem(Field, "3dgs (4DGaussians)",
                        "with " + string.Join(" and ", offOrigin) + ": 4DGaussians expects the content around the world origin — without fused.ply it starts from 2000 random points in ±1.3 about it (scene/dataset_readers.py:327–333), which also bound its deformation grid (scene/__init__.py:77–83), and it renders its video orbiting the origin at radius 4 (line 226) — but these cameras need not look at the origin.",
                        "For 4DGaussians use formation cameras with normalisation \"recentre\" or \"nerf-synthetic\" (the target at the origin, cameras aimed at it), or check that what the cameras see lies within ±1.3 of the output origin."));
            }
            return warnings;
        }

        static string CameraSourceName(CameraSourceKind kind)
        {
            switch (kind)
            {
                case CameraSourceKind.ImportedPoses: return "imported cameras";
                case CameraSourceKind.SceneCameras: return "scene cameras";
                case CameraSourceKind.AnimatedCamera: return "an animated camera";
                case CameraSourceKind.Volume: return "an inside-out volume";
                default: return kind.ToString();
            }
        }

        static string I(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
