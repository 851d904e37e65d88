using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset convert d --to nerfstudio|colmap|ngp|dynamic3dgs [--out o] [--depths]</c>: <see cref="DatasetConverter.Convert"/>, then
    /// where the files went, the warnings, and the command that trains on the result. Exit 1 when the dataset cannot
    /// be converted or a destination file exists (nothing is overwritten).
    /// </summary>
    public static class ConvertCommand
    {
        /// <summary>A folder with more written files than this is summarised as a count (COLMAP's image copies).</summary>
        const int FilesListedPerFolder = 5;

        public static int Run(string datasetFolder, ExportTarget target, string outputFolder, TextWriter stdout, TextWriter stderr, bool depths = false, ColmapOptions colmap = null,
            string objectName = null)
        {
            ConversionResult result;
            try
            {
                // An earlier convert into the same output that was killed is finished or rolled back first.
                if (Directory.Exists(datasetFolder))
                {
                    var output = objectName != null
                        ? DatasetConverter.ObjectOutputFolder(Path.GetFullPath(datasetFolder), objectName, outputFolder)
                        : DatasetConverter.OutputFolder(Path.GetFullPath(datasetFolder), target, outputFolder);
                    var recovered = Recovery.Run(output);
                    foreach (var note in recovered) stderr.WriteLine("note: " + note);
                    if (recovered.Any(n => n.Operation == "convert" && n.Finished))
                    {
                        stdout.WriteLine("converted " + Path.GetFullPath(datasetFolder) + " to " + ExportTargets.Name(target) + " into " + output + " (the interrupted earlier convert, now finished)");
                        return ToolExitCodes.Success;
                    }
                }
                result = DatasetConverter.Convert(datasetFolder, target, outputFolder, depths, colmap, objectName);
            }
            catch (InvalidParameterException e)
            {
                if (Directory.Exists(datasetFolder) && DatasetConfig.Read(datasetFolder).IsPlanOnly)
                {
                    // One line instead of one "names no image" per planned frame.
                    stderr.WriteLine("error: " + new ValidationProblem(DatasetLayout.ConfigFileName + ": imagesRendered", "false",
                        "this dataset was planned by nerf-dataset plan and has no images, but convert needs them (their size sets the intrinsics; colmap copies them).",
                        "Render the dataset with the Unity plugin (window or batch mode) and convert that folder."));
                    stderr.WriteLine("convert refused: " + Count(e.Problems.Count, "problem") + ", the first: " + e.Problems[0] + " Nothing was written.");
                    return ToolExitCodes.Failure;
                }
                foreach (var problem in e.Problems) stderr.WriteLine("error: " + problem);
                stderr.WriteLine("convert refused: " + Count(e.Problems.Count, "problem") + "; nothing was written.");
                return ToolExitCodes.Failure;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                stderr.WriteLine("error: " + e.Message);
                stderr.WriteLine("convert failed; it writes into a working folder and moves the files into place only when all are complete, " +
                                 "so nothing was overwritten and running the same command again finishes or rolls back what was interrupted.");
                return ToolExitCodes.Failure;
            }

            foreach (var warning in result.Warnings) stderr.WriteLine("warning: " + warning);
            stdout.WriteLine("converted " + Path.GetFullPath(datasetFolder) + " to " + ExportTargets.Name(target) + ":");
            foreach (var folder in result.WrittenFiles.GroupBy(Path.GetDirectoryName))
            {
                var files = folder.ToList();
                if (files.Count > FilesListedPerFolder) stdout.WriteLine("  wrote " + files.Count + " files into " + folder.Key + Path.DirectorySeparatorChar);
                else foreach (var file in files) stdout.WriteLine("  wrote " + file);
            }
            if (result.TrainCommands.Count > 0) foreach (var command in result.TrainCommands) stdout.WriteLine("train with: " + command);
            else stdout.WriteLine("train with: " + NextStep(target, result.MainFile, depths));
            return ToolExitCodes.Success;
        }

        /// <summary>The training command of Documentation~/exports.md for the export just written.</summary>
        static string NextStep(ExportTarget target, string main, bool depths)
        {
            switch (target)
            {
                case ExportTarget.Ngp:
                    return "./instant-ngp " + Quote(main) + "   (from the instant-ngp folder)";
                default:
                    return "python train.py -s " + Quote(main) + (depths ? " -d " + GaussianSplattingDepths.FolderName : "") + " --eval   (3D Gaussian Splatting)";
            }
        }

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;

        static string Count(int n, string noun) => n + " " + noun + (n == 1 ? "" : "s");
    }
}
