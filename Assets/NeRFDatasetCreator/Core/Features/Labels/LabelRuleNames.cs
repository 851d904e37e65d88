using System;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>The settings files' names of <see cref="InstanceRule"/>: "renderer", "prefab", "child".</summary>
    public static class InstanceRules
    {
        public static readonly InstanceRule[] All = { InstanceRule.Renderer, InstanceRule.PrefabInstance, InstanceRule.TargetChild };

        public static string Name(InstanceRule rule)
        {
            switch (rule)
            {
                case InstanceRule.Renderer: return "renderer";
                case InstanceRule.PrefabInstance: return "prefab";
                case InstanceRule.TargetChild: return "child";
                default: return ((int)rule).ToString(System.Globalization.CultureInfo.InvariantCulture);
            }
        }

        public static bool IsDefined(InstanceRule rule) => Array.IndexOf(All, rule) >= 0;

        public static bool TryParse(string name, out InstanceRule rule)
        {
            foreach (var candidate in All)
                if (string.Equals(Name(candidate), name, StringComparison.OrdinalIgnoreCase))
                {
                    rule = candidate;
                    return true;
                }
            rule = InstanceRule.PrefabInstance;
            return false;
        }

        public static string NameList() => string.Join(", ", All.Select(r => "\"" + Name(r) + "\""));
    }

    /// <summary>The settings files' names of <see cref="ClassSource"/>: "tag", "layer", "prefab", "name".</summary>
    public static class ClassSources
    {
        public static readonly ClassSource[] All = { ClassSource.Tag, ClassSource.Layer, ClassSource.Prefab, ClassSource.Name };

        public static string Name(ClassSource source)
        {
            switch (source)
            {
                case ClassSource.Tag: return "tag";
                case ClassSource.Layer: return "layer";
                case ClassSource.Prefab: return "prefab";
                case ClassSource.Name: return "name";
                default: return ((int)source).ToString(System.Globalization.CultureInfo.InvariantCulture);
            }
        }

        public static bool IsDefined(ClassSource source) => Array.IndexOf(All, source) >= 0;

        public static bool TryParse(string name, out ClassSource source)
        {
            foreach (var candidate in All)
                if (string.Equals(Name(candidate), name, StringComparison.OrdinalIgnoreCase))
                {
                    source = candidate;
                    return true;
                }
            source = ClassSource.Tag;
            return false;
        }

        public static string NameList() => string.Join(", ", All.Select(s => "\"" + Name(s) + "\""));
    }
}
