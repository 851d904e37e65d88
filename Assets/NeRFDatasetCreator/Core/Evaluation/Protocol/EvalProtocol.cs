using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How a dataset is meant to be trained and scored (issue 35), written beside it as <c>eval_protocol.json</c>
    /// (<see cref="EvalProtocolFile"/>): the intended background, the training and evaluation splits, the resolution
    /// factor; the compositing rule, SSIM variant, LPIPS network and the trainer flags are derived from these and
    /// written for the reader (<see cref="EvalProtocolTrainers"/>). <c>evaluate</c> and every export read it through
    /// <see cref="ProtocolBackground.For"/> and <see cref="EvalProtocolFile.Read"/>.
    /// </summary>
    public sealed class EvalProtocol
    {
        public const string White = "white", Black = "black", Random = "random", Dataset = "dataset";

        /// <summary>The values of <see cref="Background"/> and of the settings key <see cref="SettingsKey"/>.</summary>
        public static readonly string[] BackgroundNames = { White, Black, Random, Dataset };

        /// <summary>The dataset_config / settings key that chooses the background (absent: <see cref="DefaultFor"/>).</summary>
        public const string SettingsKey = "evaluationBackground";

        /// <summary>white, black, random (a random colour per training step, scored over white) or dataset (its own solid colour).</summary>
        public string Background = White;

        /// <summary>The 8-bit sRGB colour the transparent pixels are composited over for scoring (random: white).</summary>
        public byte R = 255, G = 255, B = 255;

        /// <summary>The dataset's own background as dataset_config.json states it ("transparent", "sky", "#rrggbb"), or null when unknown.</summary>
        public string DatasetBackground;

        public List<string> TrainSplits = new List<string> { "train" };
        public string EvaluationSplit = "test";
        public string ValidationSplit = "val";

        /// <summary>Renders are scored at the dataset's resolution divided by this (1: full resolution, the only factor evaluate scores).</summary>
        public int ResolutionFactor = 1;

        /// <summary>The name <c>evaluate --background</c> takes for this protocol: random scores over white.</summary>
        public string EvaluationBackgroundName => Background == Random ? White : Background;

        public string ColourText => "#" + R.ToString("x2", CultureInfo.InvariantCulture) + G.ToString("x2", CultureInfo.InvariantCulture) + B.ToString("x2", CultureInfo.InvariantCulture);

        /// <summary>What the protocol says in one line, for metrics.json, the report and messages.</summary>
        public string Describe() =>
            Background + (Background == Random ? " in training, scored over white" : Background == Dataset ? " (" + (DatasetBackground ?? ColourText) + ")" : "") +
            "; train on " + string.Join(" + ", TrainSplits) + ", evaluate on " + EvaluationSplit + "; resolution factor " + ResolutionFactor.ToString(CultureInfo.InvariantCulture);

        /// <summary>
        /// The protocol for a dataset whose background is <paramref name="dataset"/> (null: unknown, treated as
        /// transparent), with the background <paramref name="chosen"/> (null: the default). Throws
        /// <see cref="InvalidParameterException"/> naming <see cref="SettingsKey"/> when the choice contradicts the dataset.
        /// </summary>
        public static EvalProtocol For(BackgroundSettings dataset, string chosen = null)
        {
            var problem = Problem(dataset, chosen);
            if (problem != null) throw new InvalidParameterException(new[] { problem });
            var name = chosen == null ? DefaultFor(dataset) : chosen.ToLowerInvariant();
            var protocol = new EvalProtocol { Background = name, DatasetBackground = dataset?.ToConfigString() };
            if (name == Black) protocol.R = protocol.G = protocol.B = 0;
            else if (name == Dataset && dataset != null && !dataset.Transparent && !dataset.Sky)
            {
                protocol.R = Byte(dataset.R);
                protocol.G = Byte(dataset.G);
                protocol.B = Byte(dataset.B);
            }
            return protocol;
        }

        /// <summary>
        /// White for a transparent dataset (nerf_synthetic's evaluation) and for the sky (its images are opaque; white is
        /// what an RGBA render, e.g. instant-ngp's screenshot, is composited over); the dataset's own for a solid colour.
        /// </summary>
        public static string DefaultFor(BackgroundSettings dataset) => dataset == null || dataset.Transparent || dataset.Sky ? White : Dataset;

        /// <summary>Why <paramref name="chosen"/> cannot be this dataset's protocol background, or null.</summary>
        public static ValidationProblem Problem(BackgroundSettings dataset, string chosen)
        {
            if (chosen == null) return null;
            var name = chosen.ToLowerInvariant();
            if (Array.IndexOf(BackgroundNames, name) < 0)
                return new ValidationProblem(SettingsKey, chosen, "is not " + string.Join(", ", BackgroundNames) + "." + SpellingSuggestion.Sentence(chosen, BackgroundNames),
                    "Leave it out for the default (white for a transparent background, the dataset's own colour for a solid one).");
            var transparent = dataset == null || dataset.Transparent;
            if (transparent && name == Dataset)
                return new ValidationProblem(SettingsKey, chosen, "asks for the dataset's own background colour, but the background is transparent: the images have no colour behind the target.",
                    "Write \"white\" (nerf_synthetic's evaluation), \"black\" or \"random\", or leave it out for white.");
            if (!transparent && !dataset.Sky && name != Dataset)
            {
                var colour = name == White ? 255 : name == Black ? 0 : -1;
                if (colour < 0 || Byte(dataset.R) != colour || Byte(dataset.G) != colour || Byte(dataset.B) != colour)
                    return new ValidationProblem(SettingsKey, chosen, "contradicts the dataset's solid background " + dataset.ToConfigString() +
                                                                      ": its images are opaque, so a trainer sees that colour behind the target whatever its background flag.",
                        "Leave it out (or write \"dataset\") for a solid background; write \"background\": \"transparent\" to let the protocol choose the colour.");
            }
            return null;
        }

        static byte Byte(double c) => (byte)Math.Round(Math.Max(0, Math.Min(1, c)) * 255);
    }
}
