using System;
using System.Globalization;
using System.Security.Cryptography;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --background white|black|random [--seed N]</c>: the solid colour an export composites each RGBA image
    /// over (<see cref="BackgroundImages"/>). <c>random</c> gives each image its own colour, drawn from its dataset path
    /// and the seed by <see cref="RandomRule"/> (reproducible in any language, recorded per image in backgrounds.json).
    /// Only the exports whose trainers mishandle alpha take it (<see cref="Refusal"/>).
    /// </summary>
    public sealed class ExportBackground
    {
        public static readonly string[] Names = { "white", "black", "random" };

        public const string RandomRule =
            "R, G, B = the first three bytes of SHA-256 of the UTF-8 text \"<seed>/<image path>\" (image path as in the dataset's frames, e.g. train/r_0.png; seed in decimal)";

        ExportBackground(string name, long seed)
        {
            Name = name;
            Seed = seed;
        }

        /// <summary>white, black or random.</summary>
        public string Name { get; }

        /// <summary><c>--seed</c> (random only; 0 by default).</summary>
        public long Seed { get; }

        public bool IsRandom => Name == "random";

        /// <summary>Parses a <c>--background</c> value (case ignored); null with a problem naming the values otherwise.</summary>
        public static ExportBackground Parse(string value, long seed, out ValidationProblem problem)
        {
            problem = null;
            var index = Array.FindIndex(Names, n => string.Equals(n, value?.Trim(), StringComparison.OrdinalIgnoreCase));
            if (index >= 0) return new ExportBackground(Names[index], seed);
            problem = new ValidationProblem("--background", value ?? "", "is not white, black or random.",
                "Use white (nerf_synthetic's protocol), black, or random (a colour per image from --seed)." + SpellingSuggestion.Sentence(value, Names));
            return null;
        }

        /// <summary>The colour <paramref name="imagePath"/> (dataset-relative, e.g. train/r_0.png) is composited over.</summary>
        public (byte R, byte G, byte B) ColourOf(string imagePath)
        {
            if (Name == "white") return (255, 255, 255);
            if (Name == "black") return (0, 0, 0);
            using (var sha = SHA256.Create())
            {
                var hash = sha.ComputeHash(Encoding.UTF8.GetBytes(Seed.ToString(CultureInfo.InvariantCulture) + "/" + ExportPaths.Normalise(imagePath)));
                return (hash[0], hash[1], hash[2]);
            }
        }

        /// <summary>
        /// Why <paramref name="target"/> refuses <c>--background</c>, or null for colmap and nerfstudio. instant-ngp
        /// composites the RGBA images over a random colour itself while training (testbed.h <c>random_bg_color = true</c>,
        /// testbed_nerf.cu lines 965–967): opaque images would teach it the background as scenery. dynamic3dgs and
        /// gaussian-grouping write their own images and masks for their trainers.
        /// </summary>
        public static ValidationProblem Refusal(ExportTarget target, ExportBackground background)
        {
            if (target == ExportTarget.Colmap || target == ExportTarget.Nerfstudio) return null;
            var why = target == ExportTarget.Ngp
                ? "is for trainers that drop or mishandle alpha; instant-ngp composites the RGBA images over a random colour itself while training, and opaque images would teach it the background as scenery."
                : "is for the colmap and nerfstudio exports; --to " + ExportTargets.Name(target) + " writes its trainer's own images and masks.";
            return new ValidationProblem("--background", background.Name, why, "Leave --background out, or use --to colmap (3DGS, gsplat) or --to nerfstudio.");
        }
    }
}
