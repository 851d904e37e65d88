using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The camera formations a split can use; the names are those of <see cref="ICameraFormation.Kind"/>.</summary>
    public enum FormationKind
    {
        Halo,
        Sphere,
        SemiSphere,
        Random,
        Orbit,
    }

    public static class FormationKinds
    {
        public static readonly IReadOnlyList<FormationKind> All =
            new[] { FormationKind.Halo, FormationKind.Sphere, FormationKind.SemiSphere, FormationKind.Random, FormationKind.Orbit };

        public static string Name(FormationKind kind)
        {
            switch (kind)
            {
                case FormationKind.Halo: return "halo";
                case FormationKind.Sphere: return "sphere";
                case FormationKind.SemiSphere: return "semisphere";
                case FormationKind.Random: return "random";
                case FormationKind.Orbit: return "orbit";
                default: throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a formation kind");
            }
        }

        public static bool TryParse(string name, out FormationKind kind)
        {
            foreach (var k in All)
                if (string.Equals(Name(k), name, StringComparison.OrdinalIgnoreCase))
                {
                    kind = k;
                    return true;
                }
            kind = FormationKind.SemiSphere;
            return false;
        }

        public static string NameList() => string.Join(", ", new List<FormationKind>(All).ConvertAll(Name));
    }
}
