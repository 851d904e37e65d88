using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The training commands <c>convert --to colmap</c> prints (Documentation~/using-the-data.md explains both).</summary>
    public static class ColmapTraining
    {
        /// <summary>
        /// 3D Gaussian Splatting's, and — when the model has tracks — gsplat's <c>simple_trainer.py</c> with its depth
        /// loss, which takes depth from the points each image's track lists (gsplat examples/datasets/colmap.py,
        /// <c>point_indices</c>). <c>--data_factor 1</c>: its default 4 would look for an <c>images_4</c> folder.
        /// </summary>
        public static IReadOnlyList<string> Commands(string outDir, bool depths, ColmapModel model)
        {
            var commands = new List<string>
            {
                "python train.py -s " + Quote(outDir) + (depths ? " -d " + GaussianSplattingDepths.FolderName : "") + " --eval   (3D Gaussian Splatting)",
            };
            if (model != null && model.ObservationCount > 0)
                commands.Add("python simple_trainer.py default --data_dir " + Quote(outDir) + " --data_factor 1 --depth_loss --result_dir " +
                             Quote("results/" + ExportPaths.RunName(outDir, DatasetConverter.ColmapFolderName)) + "   (gsplat examples/, depth loss from the tracks)");
            return commands;
        }

        static string Quote(string path) => path.IndexOf(' ') >= 0 ? "\"" + path + "\"" : path;
    }
}
