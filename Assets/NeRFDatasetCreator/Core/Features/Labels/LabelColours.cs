using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The display colour of an id (labels.json's <c>colour</c>, the preview PNGs): hues a golden angle apart, so
    /// neighbouring ids differ clearly, with saturation and value alternating in three steps. A function of the id
    /// alone: the same id has the same colour in every capture. Id 0 (background) is black.
    /// </summary>
    public static class LabelColours
    {
        const double GoldenAngle = 0.38196601125010515; // (3 - √5) / 2 of a turn

        public static void Rgb(int id, out byte r, out byte g, out byte b)
        {
            if (id <= 0)
            {
                r = g = b = 0;
                return;
            }
            var hue = (id * GoldenAngle) % 1.0;
            var saturation = 0.85 - 0.2 * (id % 3) / 2.0;
            var value = 1.0 - 0.15 * ((id / 3) % 3) / 2.0;
            HsvToRgb(hue, saturation, value, out r, out g, out b);
        }

        /// <summary>"#rrggbb", lowercase.</summary>
        public static string Hex(int id)
        {
            Rgb(id, out var r, out var g, out var b);
            return "#" + r.ToString("x2", CultureInfo.InvariantCulture) + g.ToString("x2", CultureInfo.InvariantCulture) + b.ToString("x2", CultureInfo.InvariantCulture);
        }

        static void HsvToRgb(double h, double s, double v, out byte r, out byte g, out byte b)
        {
            var sector = h * 6;
            var i = (int)Math.Floor(sector) % 6;
            var f = sector - Math.Floor(sector);
            double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
            double rr, gg, bb;
            switch (i)
            {
                case 0: rr = v; gg = t; bb = p; break;
                case 1: rr = q; gg = v; bb = p; break;
                case 2: rr = p; gg = v; bb = t; break;
                case 3: rr = p; gg = q; bb = v; break;
                case 4: rr = t; gg = p; bb = v; break;
                default: rr = v; gg = p; bb = q; break;
            }
            r = ToByte(rr);
            g = ToByte(gg);
            b = ToByte(bb);
        }

        static byte ToByte(double c) => (byte)Math.Round(Math.Max(0, Math.Min(1, c)) * 255);
    }
}
