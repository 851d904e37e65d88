using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>The problems of the <c>"labels"</c> section the settings alone show (<see cref="SettingsValidator"/> adds them).</summary>
    public static class LabelSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var labels = settings.Labels;
            if (labels == null || !labels.Enabled) return problems;
            if (!InstanceRules.IsDefined(labels.Instances))
                problems.Add(new ValidationProblem("labels.instances", InstanceRules.Name(labels.Instances), "is not an instance rule.", "Use one of " + InstanceRules.NameList() + "."));
            if (!ClassSources.IsDefined(labels.ClassFrom))
                problems.Add(new ValidationProblem("labels.classFrom", ClassSources.Name(labels.ClassFrom), "is not a class source.", "Use one of " + ClassSources.NameList() + "."));
            var rules = labels.Classes ?? new List<ClassRule>();
            if (labels.ClassFrom == ClassSource.Name && rules.Count == 0)
                problems.Add(new ValidationProblem("labels.classes", "[]",
                    "is empty, but labels.classFrom is \"name\": every object name would be a class of its own.",
                    "Give name patterns with their classes, e.g. [{\"match\": \"Car*\", \"class\": \"car\"}], or take classes from \"tag\", \"layer\" or \"prefab\"."));
            if (rules.Count > LabelSettings.MaxRules)
                problems.Add(ValidationProblem.OutsideRange("labels.classes", rules.Count, 0, LabelSettings.MaxRules));
            var seen = new HashSet<string>(System.StringComparer.Ordinal);
            for (var i = 0; i < rules.Count && i <= LabelSettings.MaxRules; i++)
            {
                var at = "labels.classes[" + i.ToString(CultureInfo.InvariantCulture) + "]";
                var rule = rules[i];
                if (rule == null || string.IsNullOrEmpty(rule.Match))
                    problems.Add(new ValidationProblem(at + ".match", "\"\"", "is empty, so the rule matches nothing.",
                        "Give the tag, layer, prefab path or name pattern (with * and ?) the rule is for."));
                else if (!seen.Add(rule.Match))
                    problems.Add(new ValidationProblem(at + ".match", "\"" + rule.Match + "\"", "repeats an earlier rule's pattern, so this rule is never used (the first match decides).",
                        "Remove the rule or change its pattern."));
                if (rule == null || string.IsNullOrWhiteSpace(rule.Class))
                    problems.Add(new ValidationProblem(at + ".class", "\"" + (rule?.Class ?? "") + "\"", "is empty; a rule names the class its objects belong to.",
                        "Give a class name, e.g. \"car\"."));
            }
            if (labels.OtherClass != null && labels.OtherClass.Length > 0 && labels.OtherClass.Trim().Length == 0)
                problems.Add(new ValidationProblem("labels.otherClass", "\"" + labels.OtherClass + "\"", "is only spaces.",
                    "Give a class name for unmatched objects, or \"\" to leave them unlabelled (0) in the semantic maps."));
            return problems;
        }
    }
}
