using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The config names of <see cref="LightingKind"/>: "environment", "point", "spot".</summary>
    public static class LightingKinds
    {
        public static readonly string[] Names = { "environment", "point", "spot" };

        public static string Name(LightingKind kind) => Names[(int)kind];

        public static bool TryParse(string name, out LightingKind kind)
        {
            var index = Array.IndexOf(Names, name);
            kind = index >= 0 ? (LightingKind)index : LightingKind.Environment;
            return index >= 0;
        }

        public static string NameList() => "\"environment\", \"point\" or \"spot\"";

        /// <summary>The condition keys each kind reads besides "name" and "kind" (the reader refuses the others by name).</summary>
        public static IReadOnlyList<string> KeysOf(LightingKind kind)
        {
            switch (kind)
            {
                case LightingKind.Environment: return new[] { "file", "rotations", "intensity" };
                case LightingKind.Point: return new[] { "position", "intensity", "colour", "shadows" };
                default: return new[] { "position", "direction", "spotAngle", "intensity", "colour", "shadows" };
            }
        }
    }
}
