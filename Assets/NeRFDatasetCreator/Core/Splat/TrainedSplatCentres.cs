using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>evaluate --geometry &lt;trained PLY&gt;</c>: a trained splat's Gaussian centres as a point cloud in the dataset's
    /// output frame — the centres whose opacity sigmoid(logit) exceeds <see cref="OpacityThreshold"/>, moved out of the
    /// trainer's frame by the same map place-splat composes (<see cref="TrainedModel.TrainerToOutput"/>). The trainer is
    /// the one whose output folder holds the PLY: its own folder or one of its parents.
    /// </summary>
    public static class TrainedSplatCentres
    {
        /// <summary>
        /// Centres at least this opaque count as surface: half-transparent and fainter Gaussians are mostly the
        /// floaters and fringes the optimiser leaves (3DGS itself prunes below 0.005), not the object's surface.
        /// </summary>
        public const double OpacityThreshold = 0.5;

        /// <summary>How many folders up from the PLY's own the trainer's folder is looked for (3DGS: point_cloud/iteration_N is two below).</summary>
        public const int LevelsUp = 3;

        /// <summary>The centres in the output frame, and one line saying what they are.</summary>
        public static (List<Vector3d> Centres, string Kind) Read(string plyPath)
        {
            var full = Path.GetFullPath(plyPath);
            var model = FindModel(full);
            var ply = GaussianPly.ReadCentres(full, OpacityThreshold);
            var centres = ply.Centres.Select(model.TrainerToOutput.MultiplyPoint).ToList();
            var kind = "Gaussian splat (" + centres.Count + " of " + ply.Total + " centres with opacity > " + OpacityThreshold.ToString(System.Globalization.CultureInfo.InvariantCulture) +
                       ", from " + model.Trainer + " " + model.Folder + ": " + model.Frame + ", mapped into the output frame)";
            return (centres, kind);
        }

        /// <summary>The trainer output folder holding <paramref name="plyPath"/>, read as place-splat reads it with this PLY.</summary>
        static TrainedModel FindModel(string plyPath)
        {
            var dir = Path.GetDirectoryName(plyPath);
            for (var level = 0; level <= LevelsUp && !string.IsNullOrEmpty(dir); level++, dir = Path.GetDirectoryName(dir))
                if (TrainerFolders.Detect(dir).Count > 0) return TrainedModel.Find(dir, null, plyPath);
            throw TrainedModel.Refuse(GeometryFile.Reconstruction, plyPath,
                "is a Gaussian splat, but no trainer's output folder holds it (looked " + LevelsUp + " folders up for " + TrainedModel.LookedFor + "), so the frame its centres are in is unknown.",
                "Pass the PLY inside its model folder (nerfstudio: ns-export gaussian-splat --output-dir <run folder>/exports).");
        }
    }
}
