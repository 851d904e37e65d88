using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Each view's near and far bound for <c>poses_bounds.npy</c> (LLFF, N3DV), exact from the dataset's depth maps
    /// where LLFF estimates them from sparse points. LLFF means z-distances: Fyusion/LLFF llff/poses/pose_utils.py
    /// (c6e27b1) <c>save_poses</c> projects every point on the camera's back axis, <c>zs = sum(-(pts − c)·back)</c>, and
    /// keeps the 0.1 / 99.9 percentiles. Our depth PNGs hold exactly that z (along the camera axis, not the ray) at each
    /// pixel centre, in steps of <see cref="ExportScene.DepthUnitScale"/> output units, 0 = no surface
    /// (Documentation~/output-format.md), so a view's bounds are the smallest and largest non-zero steps × the step:
    /// within half a step of the nearest and farthest surface a pixel centre sees. Rules: a view whose depth map sees no
    /// surface takes the smallest near and the largest far of the other views (warned); a clamped pixel (65535: beyond
    /// the PNG's range) makes far the largest value the PNG holds (warned, a lower bound); a frame without a depth map
    /// is refused, naming how many.
    /// </summary>
    public static class DepthBounds
    {
        /// <summary>(near, far) per frame of <paramref name="frames"/>, in output units.</summary>
        /// <param name="target">The <c>--to</c> name, for the messages.</param>
        public static (double Near, double Far)[] Of(ExportScene scene, IReadOnlyList<ExportFrame> frames, string target, ICollection<ValidationProblem> warnings)
        {
            var missing = frames.Where(f => f.DepthPath == null).ToList();
            if (missing.Count > 0)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("depth", missing.Count + " of " + frames.Count + " views (first: " + missing[0].ImagePath + ")",
                        "have no usable 16-bit depth PNG, and --to " + target + " writes each view's near and far depth into poses_bounds.npy from the depth maps.",
                        "Capture with depth \"png\" in every split (settings: train/val/test depth)."),
                });
            var steps = new (int Min, int Max)?[frames.Count];
            var clamped = 0;
            for (var i = 0; i < frames.Count; i++)
            {
                var path = Path.Combine(scene.RootDirectory, frames[i].DepthPath);
                int min = int.MaxValue, max = 0;
                foreach (var v in PngGray16Reader.Read(path, out _, out _))
                {
                    if (v == 0) continue;
                    if (v < min) min = v;
                    if (v > max) max = v;
                    if (v == ushort.MaxValue) clamped++;
                }
                if (max > 0) steps[i] = (min, max);
            }
            var seen = steps.Where(s => s.HasValue).Select(s => s.Value).ToList();
            if (seen.Count == 0)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("depth", frames.Count + " depth maps", "are all 0 (no surface in any view), so there is no near or far bound to write.",
                        "Check that the target is in view and that depth was captured."),
                });
            var empty = steps.Count(s => !s.HasValue);
            if (empty > 0)
                warnings.Add(new ValidationProblem("depth", empty + " views", "see no surface, so their near and far are the smallest near and largest far of the other views.",
                    "Nothing to do, or capture views that see the target."));
            if (clamped > 0)
                warnings.Add(new ValidationProblem("depth", clamped + " pixels", "are beyond the depth PNG's range (65535 steps), so far is a lower bound in their views.",
                    "Capture closer, or with a smaller normalisation scale."));
            int allMin = seen.Min(s => s.Min), allMax = seen.Max(s => s.Max);
            var unit = scene.DepthUnitScale;
            return steps.Select(s => ((s?.Min ?? allMin) * unit, (s?.Max ?? allMax) * unit)).ToArray();
        }
    }
}
