using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A trainer's output folder as <c>place-splat</c> and <c>evaluate --geometry</c> need it: which trainer wrote it
    /// (from its files), the PLY to place, and the map from the trainer's frame back to the dataset's output frame.
    /// The folder layouts and frames, with their sources, are in Documentation~/maintainers/splat-placement.md.
    /// </summary>
    public sealed class TrainedModel
    {
        public const string GaussianSplatting = "3dgs";
        public const string Nerfstudio = "nerfstudio";
        public const string Gsplat = "gsplat";

        public static readonly IReadOnlyList<string> Trainers = new[] { GaussianSplatting, Nerfstudio, Gsplat };

        /// <summary>What a folder must hold for each trainer: every refusal names these.</summary>
        public const string LookedFor =
            "a 3DGS model folder (point_cloud/iteration_<N>/point_cloud.ply, cfg_args), a nerfstudio run folder (config.yml and dataparser_transforms.json) " +
            "or a gsplat result folder (cfg.yml and ply/point_cloud_<step>.ply)";

        internal TrainedModel(string trainer, string folder, string plyPath, Matrix4x4d outputToTrainer, string frame, List<string> notes)
        {
            Trainer = trainer;
            Folder = folder;
            PlyPath = plyPath;
            OutputToTrainer = outputToTrainer;
            TrainerToOutput = AffineMaps.Inverse(outputToTrainer);
            Frame = frame;
            Notes = notes;
        }

        /// <summary>"3dgs", "nerfstudio" or "gsplat".</summary>
        public string Trainer { get; }

        /// <summary>The model folder, full path.</summary>
        public string Folder { get; }

        /// <summary>The PLY to place, full path.</summary>
        public string PlyPath { get; }

        /// <summary>x_trainer = OutputToTrainer·[x_out, 1]: what the trainer did to the dataset's world.</summary>
        public Matrix4x4d OutputToTrainer { get; }

        /// <summary>The inverse: a Gaussian centre of the PLY into the dataset's output frame.</summary>
        public Matrix4x4d TrainerToOutput { get; }

        /// <summary>One line on the trainer's frame, e.g. "nerfstudio's dataparser frame (dataparser_transforms.json: ...)".</summary>
        public string Frame { get; }

        /// <summary>Choices made and things the user should know.</summary>
        public List<string> Notes { get; }

        /// <summary>
        /// Reads the trained output in <paramref name="model"/>. <paramref name="trainer"/> (null: detect) must agree with
        /// the folder; <paramref name="ply"/> replaces the PLY found there (nerfstudio's <c>ns-export --output-dir</c>).
        /// Refusals are <see cref="InvalidParameterException"/>s naming the option and what was looked for.
        /// </summary>
        public static TrainedModel Find(string model, string trainer = null, string ply = null)
        {
            if (string.IsNullOrWhiteSpace(model) || !Directory.Exists(model))
                throw Refuse("--model", model ?? "(missing)", "is not an existing folder.", "Pass the trained output: " + LookedFor + ".");
            var folder = Path.GetFullPath(model).TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
            if (trainer != null && !Trainers.Contains(trainer))
                throw Refuse("--trainer", trainer, "is not a trainer this tool places.", "Use --trainer " + string.Join("|", Trainers) + ", or leave it out to detect the trainer from the folder.");
            if (ply != null && !File.Exists(ply))
                throw Refuse("--ply", ply, "is not an existing file.", "Pass the PLY the trainer or its exporter wrote (nerfstudio: ns-export gaussian-splat writes splat.ply in --output-dir).");
            var found = TrainerFolders.Detect(folder);
            if (found.Count == 0)
                throw Refuse("--model", folder, "holds none of the files a trainer leaves: looked for " + LookedFor + ".",
                    "Pass the folder train.py -m, ns-train (outputs/<name>/splatfacto/<timestamp>) or simple_trainer.py --result_dir wrote.");
            if (trainer != null && found.All(f => f.Trainer != trainer))
                throw Refuse("--trainer", trainer, "contradicts the folder: " + folder + " is a " + Describe(found) + ".",
                    "Leave --trainer out, or pass the " + trainer + " output folder.");
            if (trainer == null && found.Count > 1)
                throw Refuse("--model", folder, "looks like more than one trainer's output: " + Describe(found) + ".", "Say which with --trainer " + string.Join("|", found.Select(f => f.Trainer)) + ".");
            var chosen = trainer ?? found[0].Trainer;
            var plyPath = ply == null ? null : Path.GetFullPath(ply);
            switch (chosen)
            {
                case GaussianSplatting: return TrainerFolders.GaussianSplattingModel(folder, plyPath);
                case Nerfstudio: return TrainerFolders.NerfstudioRun(folder, plyPath);
                default: return TrainerFolders.GsplatResult(folder, plyPath);
            }
        }

        static string Describe(IEnumerable<TrainerFolders.Evidence> found) =>
            string.Join(" and a ", found.Select(f => f.Trainer + " output (found " + f.Files + ")"));

        internal static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
