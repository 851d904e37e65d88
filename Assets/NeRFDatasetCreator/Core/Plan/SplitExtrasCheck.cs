using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Plan-time warning when the splits a capture writes differ in depth PNGs or masks: nerfstudio-data asserts that
    /// <c>depth_file_path</c> and <c>mask_path</c> are on every frame or on none (nerfstudio_dataparser.py:185–191), so
    /// the nerfstudio export leaves out whatever one split lacks, for all splits. (instant-ngp reads the train split's
    /// depth only and 3DGS's depth export marks images without depth unreliable, so they are unaffected.)
    /// </summary>
    static class SplitExtrasCheck
    {
        public static IEnumerable<ValidationProblem> For(DatasetSettings settings)
        {
            var used = DatasetSplits.All.Where(s => settings.Split(s).Count > 0).ToList();
            var depth = used.Where(s => ExtraOutputs.HasPng(settings.Split(s).Depth)).ToList();
            if (depth.Count > 0 && depth.Count < used.Count)
                yield return Problem("depth", used.Except(depth), depth, "\"png\"");
            var masks = used.Where(s => settings.Split(s).Mask).ToList();
            if (masks.Count > 0 && masks.Count < used.Count)
                yield return Problem("mask", used.Except(masks), masks, "true");
        }

        static ValidationProblem Problem(string key, IEnumerable<DatasetSplit> without, List<DatasetSplit> with, string value)
        {
            var missing = without.Select(DatasetSplits.Name).ToList();
            var having = string.Join(" and ", with.Select(DatasetSplits.Name));
            return new ValidationProblem("splits." + missing[0] + "." + key, "none",
                $"differs from {having}: nerfstudio needs {key} on every frame or none, so its export will leave {key} out of every split.",
                $"Set {key} to {value} in {string.Join(" and ", missing)} as well (or leave nerfstudio out of loaders).");
        }
    }
}
