using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The file-name keys of the relighting conditions (contract of issue 38): a point or spot light's key is its name
    /// (<c>olat-00</c>), an environment's is its name and each rotation in three digits (<c>sunset_090</c>), in the
    /// settings' order. Each key is one more colour image per view: <c>r_&lt;i&gt;_light_&lt;key&gt;.png</c>.
    /// </summary>
    public static class LightingKeys
    {
        /// <summary><c>sunset_090</c>: an environment at a rotation (a whole number of degrees, 0…359).</summary>
        public static string Environment(string name, double rotation) =>
            name + "_" + ((int)rotation).ToString("000", CultureInfo.InvariantCulture);

        /// <summary>The keys of one condition: one per rotation of an environment, its name for a point or spot light.</summary>
        public static IReadOnlyList<string> Of(LightingCondition condition)
        {
            if (condition.Kind != LightingKind.Environment) return new[] { condition.Name };
            var keys = new List<string>();
            foreach (var rotation in condition.Rotations ?? new double[0]) keys.Add(Environment(condition.Name, rotation));
            return keys;
        }

        /// <summary>Every key of the settings' relighting, in order; empty when relighting is off.</summary>
        public static IReadOnlyList<string> All(DatasetSettings settings)
        {
            var keys = new List<string>();
            var relighting = settings?.Relighting;
            if (relighting == null || !relighting.Enabled) return keys;
            foreach (var condition in relighting.Conditions)
                if (condition != null) keys.AddRange(Of(condition));
            return keys;
        }

        /// <summary>The relit kinds a split's views write: every split with relighting on, the EXRs where <c>hdr</c> applies too.</summary>
        internal static void AddFileKinds(DatasetSettings settings, DatasetSplit split, List<DatasetFileKind> kinds)
        {
            if (All(settings).Count == 0) return;
            kinds.Add(DatasetFileKind.RelitPng);
            if (settings.Hdr != null && settings.Hdr.Applies(split)) kinds.Add(DatasetFileKind.RelitHdrExr);
        }
    }
}
