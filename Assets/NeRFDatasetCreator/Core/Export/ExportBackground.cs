using System;
using System.Globalization;
using System.Security.Cryptography;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --background white|black|random|protocol [--seed N]</c>: the solid colour an export composites each RGBA image
    /// over (<see cref="BackgroundImages"/>). <c>random</c> gives each image its own colour, drawn from its dataset path
    /// and the seed by <see cref="RandomRule"/> (reproducible in any language, recorded per image in backgrounds.json);
    /// <c>protocol</c> is the dataset's own, as <see cref="ProtocolBackground.For"/> says (<see cref="Resolve"/>).
    /// Only the exports whose trainers mishandle alpha take it (<see cref="Refusal"/>).
    /// </summary>
    public sealed class ExportBackground
    {
        public static readonly string[] Names = { "white", "black", "random", "protocol" };

        public const string RandomRule =
            "R, G, B = the first three bytes of SHA-256 of the UTF-8 text \"<seed>/<image path>\" (image path as in the dataset's frames, e.g. train/r_0.png; seed in decimal)";

        ExportBackground(string name, long seed, (byte R, byte G, byte B)? colour = null, bool fromProtocol = false)
        {
            Name = name;
            Seed = seed;
            _colour = colour;
            FromProtocol = fromProtocol;
        }

        readonly (byte R, byte G, byte B)? _colour;

        /// <summary>white, black or random; after <see cref="Resolve"/>, protocol becomes the protocol's name (white, black, dataset).</summary>
        public string Name { get; }

        /// <summary>Whether the colour is the dataset's protocol background (<c>--background protocol</c>).</summary>
        public bool FromProtocol { get; }

        /// <summary>
        /// <c>protocol</c> made concrete for the dataset in <paramref name="datasetRoot"/>: the one place exports ask
        /// (<see cref="ProtocolBackground.For"/>); every other value is returned as it is.
        /// </summary>
        public ExportBackground Resolve(string datasetRoot)
        {
            if (Name != "protocol" || FromProtocol) return this;
            var p = ProtocolBackground.For(datasetRoot);
            return new ExportBackground(p.Name, Seed, (p.R, p.G, p.B), fromProtocol: true);
        }

        /// <summary><c>--seed</c> (random only; 0 by default).</summary>
        public long Seed { get; }

        public bool IsRandom => Name == "random";

        /// <summary>Parses a <c>--background</c> value (case ignored); null with a problem naming the values otherwise.</summary>
        public static ExportBackground Parse(string value, long seed, out ValidationProblem problem)
        {
            problem = null;
            var index = Array.FindIndex(Names, n => string.Equals(n, value?.Trim(), StringComparison.OrdinalIgnoreCase));
            if (index >= 0) return new ExportBackground(Names[index], seed);
            problem = new ValidationProblem("--background", value ?? "", "is not white, black, random or protocol.",
                "Use white (nerf_synthetic's protocol), black, random (a colour per image from --seed) or protocol (the dataset's)." + SpellingSuggestion.Sentence(value, Names));
            return null;
        }

        /// <summary>The colour <paramref name="imagePath"/> (dataset-relative, e.g. train/r_0.png) is composited over.</summary>
        public (byte R, byte G, byte B) ColourOf(string imagePath)
        {
            if (_colour.HasValue) return _colour.Value;
            if (Name == "protocol") throw new System.InvalidOperationException("Resolve --background protocol against the dataset first.");
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
