using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>The Editor's <i>Place trained splat</i> trainer popup and its text for a placement (issue 34).</summary>
    public static class SplatTrainerChoice
    {
        /// <summary>The popup's entries: "auto" detects the trainer from the folder.</summary>
        public static readonly string[] Names = { "auto", "3dgs", "nerfstudio", "gsplat" };

        /// <summary>The <c>trainer</c> argument of <see cref="SplatPlacer.Place"/>: null for "auto".</summary>
        public static string Argument(int index)
        {
            if (index < 0 || index >= Names.Length) throw new ArgumentOutOfRangeException(nameof(index), index, "One of " + string.Join(", ", Names) + ".");
            return index == 0 ? null : Names[index];
        }

        /// <summary>What the window shows for a placement: trainer, PLY, the Transform's values, the matrix, cameras.json, notes.</summary>
        public static IReadOnlyList<string> Describe(SplatPlacement placement)
        {
            if (placement == null) throw new ArgumentNullException(nameof(placement));
            var lines = new List<string>
            {
                "Trainer: " + placement.Trainer,
                "PLY: " + placement.PlyPath,
                "Position: " + Numbers(placement.Position),
                "Rotation (quaternion x, y, z, w): " + Numbers(placement.Rotation),
                "Scale: " + Numbers(placement.Scale),
                "object_to_world (row-major):",
            };
            var m = placement.ObjectToWorld;
            if (m != null && m.Length == 16)
                for (var row = 0; row < 4; row++) lines.Add("  " + Numbers(m.Skip(row * 4).Take(4).ToArray()));
            lines.Add("cameras.json: " + (placement.CamerasJsonPath ?? "not written"));
            lines.AddRange(placement.Notes);
            return lines;
        }

        static string Numbers(double[] values) => values == null
            ? "—"
            : "(" + string.Join(", ", values.Select(v => v.ToString("R", CultureInfo.InvariantCulture))) + ")";
    }
}
