using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The problems of the "materials" section (<see cref="SettingsValidator"/> adds them), each naming its key.</summary>
    public static class MaterialPassSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var m = settings?.Materials;
            if (m == null || !m.Enabled) return problems;
            if (MaterialPassNames.On(m).Count == 0)
                problems.Add(new ValidationProblem(MaterialPassSettingsJson.Key + "." + MaterialPassSettingsJson.PassesKey, "[]",
                    "is empty, so no material pass would be written.",
                    "List the passes, e.g. [\"albedo\", \"metallic\", \"roughness\"], or remove the \"materials\" section."));
            return problems;
        }
    }
}
