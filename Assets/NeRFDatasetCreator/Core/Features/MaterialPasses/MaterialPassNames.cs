using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The pass names of the "materials" section (<c>"passes": ["albedo", …]</c>), in the one order every list of them
    /// uses (settings, files, frame keys, dataset_config.json), and which of a <see cref="MaterialPassSettings"/> is on.
    /// </summary>
    public static class MaterialPassNames
    {
        public const string Albedo = "albedo", Metallic = "metallic", Roughness = "roughness", Specular = "specular", Emission = "emission";

        public static readonly string[] All = { Albedo, Metallic, Roughness, Specular, Emission };

        /// <summary>Whether <paramref name="settings"/> write the pass <paramref name="name"/> (one of <see cref="All"/>).</summary>
        public static bool IsOn(MaterialPassSettings settings, string name)
        {
            switch (name)
            {
                case Albedo: return settings.Albedo;
                case Metallic: return settings.Metallic;
                case Roughness: return settings.Roughness;
                case Specular: return settings.Specular;
                case Emission: return settings.Emission;
                default: return false;
            }
        }

        /// <summary>Turns the pass <paramref name="name"/> on; false when it is not a pass name.</summary>
        public static bool TurnOn(MaterialPassSettings settings, string name)
        {
            switch (name)
            {
                case Albedo: settings.Albedo = true; return true;
                case Metallic: settings.Metallic = true; return true;
                case Roughness: settings.Roughness = true; return true;
                case Specular: settings.Specular = true; return true;
                case Emission: settings.Emission = true; return true;
                default: return false;
            }
        }

        /// <summary>The passes that are on, in <see cref="All"/>'s order.</summary>
        public static List<string> On(MaterialPassSettings settings)
        {
            var on = new List<string>();
            foreach (var name in All)
                if (IsOn(settings, name)) on.Add(name);
            return on;
        }
    }
}
