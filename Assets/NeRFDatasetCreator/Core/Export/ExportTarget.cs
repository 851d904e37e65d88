using System;
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
    }

    public static class ExportTargets
    {
        public static readonly string[] Names = { "nerfstudio", "colmap", "ngp", "dynamic3dgs", "gaussian-grouping" };

        public static string Name(ExportTarget target) => Names[(int)target];

        /// <summary>Parses a <c>--to</c> value; null with a problem naming the valid values otherwise.</summary>
        public static ExportTarget? Parse(string value, out ValidationProblem problem)
        {
            var index = Array.FindIndex(Names, n => string.Equals(n, value?.Trim(), StringComparison.OrdinalIgnoreCase));
            problem = index >= 0 ? null : new ValidationProblem("--to", value ?? "", "is not an export format.", "Use one of: " + string.Join(", ", Names.Select(n => n)) + "." + SpellingSuggestion.Sentence(value, Names));
            return index >= 0 ? (ExportTarget?)index : null;
        }
    }
}
