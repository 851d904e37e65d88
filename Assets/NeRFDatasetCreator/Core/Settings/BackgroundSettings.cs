using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The background behind the target: transparent (alpha 0, straight alpha — what every loader composites
    /// onto its own background colour) or an opaque solid colour given as sRGB components in [0, 1].
    /// </summary>
    [Serializable]
    public sealed class BackgroundSettings
    {
        public bool Transparent = true;
        public double R = 1;
        public double G = 1;
        public double B = 1;

        public BackgroundSettings Clone() => (BackgroundSettings)MemberwiseClone();

        /// <summary>"transparent" or "#rrggbb", the config-file form.</summary>
        public string ToConfigString()
        {
            if (Transparent) return "transparent";
            return "#" + Byte(R).ToString("x2", CultureInfo.InvariantCulture) + Byte(G).ToString("x2", CultureInfo.InvariantCulture) +
                   Byte(B).ToString("x2", CultureInfo.InvariantCulture);
        }

        static int Byte(double c) => (int)Math.Round(Math.Max(0, Math.Min(1, c)) * 255);

        /// <summary>Parses "transparent" or "#rrggbb"; null when the text is neither.</summary>
        public static BackgroundSettings Parse(string text)
        {
            if (text == null) return null;
            var t = text.Trim();
            if (string.Equals(t, "transparent", StringComparison.OrdinalIgnoreCase)) return new BackgroundSettings();
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
