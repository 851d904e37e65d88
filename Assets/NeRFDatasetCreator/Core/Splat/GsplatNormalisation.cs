using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// gsplat's <c>normalize_world_space</c> (its default): the COLMAP parser moves the world by a similarity it computes
    /// from the cameras and the points and saves nowhere (examples/datasets/colmap.py, normalize.py).
    /// </summary>
    public static class GsplatNormalisation
    {
        /// <param name="assumedDefault">cfg.yml has no normalize_world_space key (gsplat's default is on).</param>
        public static TrainedModel Place(string folder, string ply, string dataDir, bool assumedDefault, List<string> notes)
        {
            throw TrainedModel.Refuse(TrainerFolders.GsplatConfig + ": normalize_world_space", assumedDefault ? "(missing: gsplat's default, true)" : "true",
                "means gsplat moved the world by a normalisation it saves nowhere, so the splat cannot be placed exactly.",
                "Train again with --no-normalize-world-space (the splat then stays in the dataset's frame).");
        }
    }
}
