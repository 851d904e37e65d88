using System.Collections.Generic;

namespace NerfDatasetCreator.Editor
{
    /// <summary>The passes the settings' "materials" section asks for, in render order (null when the section is off).</summary>
    public static class MaterialPassSelection
    {
        public static IReadOnlyList<MaterialPassKind> Kinds(MaterialPassSettings settings)
        {
            if (settings == null || !settings.Enabled) return null;
            var kinds = new List<MaterialPassKind>();
            if (settings.Albedo) kinds.Add(MaterialPassKind.Albedo);
            if (settings.Metallic) kinds.Add(MaterialPassKind.Metallic);
            // The shader's smoothness is rendered; roughness = 1 − smoothness is computed from it (MaterialValues.Scalar).
            if (settings.Roughness) kinds.Add(MaterialPassKind.Smoothness);
            if (settings.Specular) kinds.Add(MaterialPassKind.Specular);
            if (settings.Emission) kinds.Add(MaterialPassKind.Emission);
            return kinds.Count == 0 ? null : kinds;
        }
    }
}
