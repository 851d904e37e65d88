using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The colour transparent pixels are composited on before scoring: rgb·a + bg·(1 − a) on the stored (sRGB) values,
    /// as every Blender-data loader does (3DGS <c>readCamerasFromTransforms</c>, nerf-pytorch <c>--white_bkgd</c>).
    /// <c>white</c> is how nerf_synthetic is evaluated and how models trained with 3DGS <c>-w</c>, nerfstudio
    /// <c>blender-data</c> (alpha_color white) or nerf-pytorch <c>--white_bkgd</c> render; <c>black</c> is 3DGS without
    /// <c>-w</c>; <c>dataset</c> is the dataset's own solid background colour (<c>settings.background</c> "#rrggbb" in
    /// dataset_config.json) — refused for a transparent dataset, whose images have no colour behind the target.
    /// </summary>
    public sealed class EvaluationBackground
    {
        public static readonly string[] Names = { "white", "black", "dataset" };

        EvaluationBackground(string name, double r, double g, double b, bool known)
        {
            Name = name;
            R = r;
            G = g;
            B = b;
            Known = known;
        }

        public string Name { get; }
        public double R { get; }
        public double G { get; }
        public double B { get; }

        /// <summary>False for <c>dataset</c> when the dataset has no solid colour: any transparent pixel is then refused.</summary>
        public bool Known { get; }

        public static EvaluationBackground White => new EvaluationBackground("white", 1, 1, 1, true);
        public static EvaluationBackground Black => new EvaluationBackground("black", 0, 0, 0, true);

        /// <summary>The background named on the command line; for "dataset" the colour recorded in <paramref name="config"/>.</summary>
        public static EvaluationBackground Parse(string name, DatasetConfig config)
        {
            switch ((name ?? "white").ToLowerInvariant())
            {
                case "white": return White;
                case "black": return Black;
                case "dataset":
                    var text = config?.BackgroundText;
                    var settings = BackgroundSettings.Parse(text);
                    if (settings != null && !settings.Transparent && !settings.Sky)
                        return new EvaluationBackground("dataset (" + text + ")", settings.R, settings.G, settings.B, true);
                    return new EvaluationBackground("dataset (" + (text ?? "unknown") + ")", 0, 0, 0, false);
                default:
                    throw new InvalidParameterException(new[] { new ValidationProblem("--background", name, "is not " + string.Join(", ", Names) + ".", "Write --background white (nerf_synthetic's evaluation), black or dataset.") });
            }
        }

        public string Describe() => Known
            ? Name + ": stored sRGB values composited as rgb·a + (" + Format(R) + ", " + Format(G) + ", " + Format(B) + ")·(1 − a)"
            : Name + ": images used as stored; a transparent pixel is refused";

        static string Format(double v) => v.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture);
    }
}
