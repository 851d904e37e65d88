using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>The formats <c>nerf-dataset convert --to</c> writes.</summary>
    public enum ExportTarget
    {
        Nerfstudio,
        Colmap,
        Ngp,

        /// <summary>Dynamic 3D Gaussians' per-time-step multi-view layout (<see cref="Dynamic3DGaussiansExport"/>).</summary>
        Dynamic3dgs,

        /// <summary>Gaussian Grouping's COLMAP layout with per-image object masks (<see cref="GaussianGroupingExport"/>).</summary>
        GaussianGrouping,

        /// <summary>Nerfies / HyperNeRF's layout from a dynamic capture; 4DGaussians reads it too (<see cref="NerfiesExport"/>).</summary>
        Nerfies,

        /// <summary>DyCheck's iPhone layout from a dynamic capture, with exact depth (<see cref="DyCheckExport"/>).</summary>
        Dycheck,

        /// <summary>LLFF's poses_bounds.npy and images/ (<see cref="LlffExport"/>).</summary>
        Llff,

        /// <summary>N3DV as 4DGaussians reads it (<see cref="DynerfExport"/>).</summary>
        Dynerf,

        /// <summary>NeuS / IDR: cameras_sphere.npz, image/, mask/ (<see cref="NeusExport"/>).</summary>
        Neus,

        /// <summary>A Replica RGB-D sequence for SplaTAM, MonoGS and Gaussian-SLAM (<see cref="ReplicaExport"/>).</summary>
        Replica,

        /// <summary>A TUM RGB-D sequence for SplaTAM, MonoGS and Gaussian-SLAM (<see cref="TumRgbdExport"/>).</summary>
        Tum,

        /// <summary>gsplat's images_2/4/8 beside a COLMAP model, and mip-NeRF's multi-scale Blender layout (<see cref="MultiscaleExport"/>).</summary>
        Multiscale,

        /// <summary>HDR-NeRF's synthetic layout: five exposure brackets per view from the linear HDR colour (<see cref="HdrNerfExport"/>).</summary>
        HdrNerf,

        /// <summary>TensoIR-Synthetic's per-view layout, which NeRFactor reads too: albedo, normals, relit views (<see cref="TensoIRExport"/>).</summary>
        Tensoir,

        /// <summary>GS-IR: TensoIR's layout through its Blender reader (<see cref="GsIr"/>).</summary>
        GsIr,

        /// <summary>Relightable 3D Gaussians' Synthetic4Relight layout (<see cref="R3dgExport"/>).</summary>
        R3dg,

        /// <summary>Kubric / MOVi scene folders with 16-bit forward and backward flow from flow/ (<see cref="KubricExport"/>).</summary>
        Kubric,

        /// <summary>Neural Scene Flow Fields' scene folders with flow_i1/ npz, disp/ and motion_masks/ from flow/ (<see cref="NsffExport"/>).</summary>
        Nsff,

        /// <summary>Shape of Motion's iPhone layout with exact tracks from flow/ (<see cref="ShapeOfMotionExport"/>).</summary>
        ShapeOfMotion,
    }

    public static class ExportTargets
    {
        public static readonly string[] Names =
        {
            "nerfstudio", "colmap", "ngp", "dynamic3dgs", "gaussian-grouping", "nerfies", "dycheck", "llff", "dynerf", "neus",
            "replica", "tum", "multiscale", "hdr-nerf",
            "tensoir", "gs-ir", "r3dg", "kubric", "nsff", "shape-of-motion",
        };

        /// <summary>
        /// The config's <c>loaders</c> names (<see cref="TargetLoaderNames"/>) that name an export too, so one
        /// vocabulary works in the config and on the command line: 3D Gaussian Splatting reads a COLMAP source, and
        /// instant-ngp reads the ngp export. (nerfstudio is the same word in both.)
        /// </summary>
        static readonly KeyValuePair<string, ExportTarget>[] LoaderNames =
        {
            new KeyValuePair<string, ExportTarget>("3dgs", ExportTarget.Colmap),
            new KeyValuePair<string, ExportTarget>("instant-ngp", ExportTarget.Ngp),
            // Not a config loader but a trainer that reads the COLMAP export as it is (convert prints its command too),
            // and the name a gsplat user types first.
            new KeyValuePair<string, ExportTarget>("gsplat", ExportTarget.Colmap),
        };

        /// <summary>The names of the format the dataset is already in: the Blender loaders read the folder as it is.</summary>
        static readonly string[] AlreadyNames = { "nerf", "blender" };

        /// <summary>
        /// <see cref="Accepted"/> with the trainers' names first: a tie goes to the earlier name, and "3dg" is one edit from
        /// both "3dgs" and "r3dg" — the 3DGS user is the likelier writer.
        /// </summary>
        static IEnumerable<string> SuggestionOrder => LoaderNames.Select(p => p.Key).Concat(Names);

        /// <summary>Every name <c>--to</c> accepts (a suggestion may be any of them).</summary>
        public static IEnumerable<string> Accepted => Names.Concat(LoaderNames.Select(p => p.Key));

        public static string Name(ExportTarget target) => Names[(int)target];

        /// <summary>Parses a <c>--to</c> value (an export name or a config loader name, case ignored); null with a problem naming the valid values otherwise.</summary>
        public static ExportTarget? Parse(string value, out ValidationProblem problem)
        {
            problem = null;
            var written = value?.Trim();
            var index = Array.FindIndex(Names, n => string.Equals(n, written, StringComparison.OrdinalIgnoreCase));
            if (index >= 0) return (ExportTarget)index;
            foreach (var pair in LoaderNames)
                if (string.Equals(pair.Key, written, StringComparison.OrdinalIgnoreCase)) return pair.Value;
            if (AlreadyNames.Any(n => string.Equals(n, written, StringComparison.OrdinalIgnoreCase)))
            {
                problem = new ValidationProblem("--to", value, "is the format the dataset is already in (nerf_synthetic / Blender): nerf, nerf-pytorch and the other Blender loaders read the dataset folder as it is.",
                    "Point the trainer at the dataset folder, or convert to one of: " + string.Join(", ", Names) + ".");
                return null;
            }
            problem = new ValidationProblem("--to", value ?? "", "is not an export format.",
                "Use one of: " + string.Join(", ", Names) + " (or the trainers' names 3dgs = gsplat = colmap, instant-ngp = ngp)." + SpellingSuggestion.Sentence(written, SuggestionOrder));
            return null;
        }
    }
}
