using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The background behind the target: transparent (alpha 0, straight alpha — what every loader composites
    /// onto its own background colour), an opaque solid colour given as sRGB components in [0, 1], or the scene's
    /// sky (<see cref="Sky"/>: rendered by the capture camera, alpha 255 everywhere — environment capture).
    /// </summary>
    [Serializable]
    public sealed class BackgroundSettings
    {
        public bool Transparent = true;
        public double R = 1;
        public double G = 1;
        public double B = 1;

        /// <summary>
        /// The scene's skybox behind everything (config <c>"sky"</c>; <see cref="Transparent"/> is then false): every
        /// pixel is what the camera sees, alpha 255. R, G, B are not used.
        /// </summary>
        public bool Sky;

        public BackgroundSettings Clone() => (BackgroundSettings)MemberwiseClone();

        /// <summary>"transparent", "sky" or "#rrggbb", the config-file form.</summary>
        public string ToConfigString()
        {
            if (Transparent) return "transparent";
            if (Sky) return "sky";
            return "#" + Byte(R).ToString("x2", CultureInfo.InvariantCulture) + Byte(G).ToString("x2", CultureInfo.InvariantCulture) +
                   Byte(B).ToString("x2", CultureInfo.InvariantCulture);
        }

        static int Byte(double c) => (int)Math.Round(Math.Max(0, Math.Min(1, c)) * 255);

        /// <summary>Parses "transparent", "sky" or "#rrggbb"; null when the text is none of them.</summary>
        public static BackgroundSettings Parse(string text)
        {
            if (text == null) return null;
            var t = text.Trim();
            if (string.Equals(t, "transparent", StringComparison.OrdinalIgnoreCase)) return new BackgroundSettings();
            if (string.Equals(t, "sky", StringComparison.OrdinalIgnoreCase)) return new BackgroundSettings { Transparent = false, Sky = true };
            if (t.Length != 7 || t[0] != '#') return null;
            if (!int.TryParse(t.Substring(1), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out var rgb)) return null;
            return new BackgroundSettings
            {
                Transparent = false,
                R = ((rgb >> 16) & 0xff) / 255.0,
                G = ((rgb >> 8) & 0xff) / 255.0,
                B = (rgb & 0xff) / 255.0,
            };
        }
    }
}
