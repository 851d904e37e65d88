using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whether a dataset's <c>points3d.ply</c> is the target's surface this plugin sampled: its SHA-256 must equal the
    /// <see cref="PointCloudRecord"/> in dataset_config.json (and the file carries <see cref="PlyWriter.Signature"/>).
    /// Any other file under that name is foreign — typically the random [−1.3, 1.3]³ cloud 3DGS writes into a Blender
    /// dataset that has none — and is never used as the target's surface: no nerfstudio <c>ply_file_path</c>, no COLMAP
    /// points3D from it. Shared by convert and validate so both say the same thing.
    /// </summary>
    public static class PointCloudOwnership
    {
        public const string FileName = "points3d.ply";

        /// <summary>
        /// True when <c>points3d.ply</c> exists and is ours. Adds a warning for a foreign file, and for a recorded cloud
        /// that is missing.
        /// </summary>
        public static bool IsOwn(string datasetDirectory, ICollection<ValidationProblem> warnings) =>
            IsOwn(datasetDirectory, DatasetConfig.Read(datasetDirectory), warnings);

        /// <param name="config">The dataset's <c>dataset_config.json</c>; without a readable record the cloud is not ours.</param>
        public static bool IsOwn(string datasetDirectory, DatasetConfigFile config, ICollection<ValidationProblem> warnings)
        {
            var path = Path.Combine(datasetDirectory, FileName);
            var record = config.Config?.PointCloud;
            if (!File.Exists(path))
            {
                if (record != null)
                    warnings?.Add(new ValidationProblem(FileName, "missing",
                        "is recorded in " + DatasetLayout.ConfigFileName + " (" + record.Points + " points) but is not in the dataset; 3DGS will start from random points.",
                        "Copy the file back from the original capture, or re-capture."));
                return false;
            }
            string why;
            try
            {
                if (record == null || record.File != FileName)
                    why = HasSignature(path)
                        ? "carries this plugin's header comment but " + DatasetLayout.ConfigFileName + " holds no record of it, so it cannot be checked"
                        : "was not written by this plugin (no record in " + DatasetLayout.ConfigFileName + ", no " + PluginInfo.Name + " header comment)";
                else if (PointCloudRecord.HashOf(path) != record.Sha256)
                    why = "differs from the cloud this plugin wrote (its SHA-256 is not the one in " + DatasetLayout.ConfigFileName + ")";
                else return true;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                // A pipe, a device or an unreadable file under this name (ReadableFile refuses it unopened): not the target's surface.
                warnings?.Add(new ValidationProblem(FileName, "unreadable", "cannot be read (" + e.Message + "), so it is NOT used as the target's surface.",
                    "Restore points3d.ply from the capture, or delete it."));
                return false;
            }
            warnings?.Add(new ValidationProblem(FileName, "foreign",
                why + ". It is most likely the random [−1.3, 1.3]³ cloud 3DGS writes into a Blender dataset without one, and is NOT used as the target's surface (no nerfstudio ply_file_path, no COLMAP points3D from it).",
                "Delete it (3DGS makes a new random one when it needs it), or capture with pointCloudPoints > 0 for the target's real surface."));
            return false;
        }

        /// <summary>Whether one of the header's first 16 lines is our signature comment (<see cref="PlyWriter.Signature"/>).</summary>
        static bool HasSignature(string path)
        {
            using (var file = ReadableFile.OpenRead(path, long.MaxValue))
                return PlyHeader.Read(file, maxLines: 16).Lines.Contains("comment " + PlyWriter.Signature);
        }
    }
}
