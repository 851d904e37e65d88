using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The problems of the "hdr" section (<see cref="SettingsValidator"/> adds them), each naming its key.</summary>
    public static class HdrSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var h = settings?.Hdr;
            if (h == null || !h.Enabled) return problems;
            if (!h.Train && !h.Val && !h.Test)
                problems.Add(new ValidationProblem("hdr.splits", "[]", "is empty, so no view would get its r_<i>_hdr.exr.",
                    "List the splits, e.g. [\"train\", \"test\"], or remove the \"hdr\" section."));
            return problems;
        }
    }
}
