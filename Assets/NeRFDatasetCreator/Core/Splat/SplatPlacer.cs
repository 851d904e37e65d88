namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset place-splat</c> and the Editor's <i>Place trained splat</i>: finds the trained model's PLY, detects
    /// its trainer, composes the trainer's frame with the dataset's <c>unity_frame</c>, and writes the viewer's
    /// <c>cameras.json</c> (issue 34).
    /// </summary>
    public static class SplatPlacer
    {
        /// <param name="datasetDir">The dataset folder (<c>dataset_config.json</c> and the transforms files).</param>
        /// <param name="model">The trained output: a 3DGS model folder, a nerfstudio run folder, a gsplat result folder.</param>
        /// <param name="trainer">"3dgs", "nerfstudio", "gsplat", or null to detect it from the folder.</param>
        /// <param name="ply">The PLY to place when the trainer wrote it elsewhere (nerfstudio's <c>ns-export --output-dir</c>), or null.</param>
        /// <param name="writeCameras">Write a 3DGS-format cameras.json where the viewer finds it (never over an existing file).</param>
        public static SplatPlacement Place(string datasetDir, string model, string trainer = null, string ply = null, bool writeCameras = true)
        {
            // Being built under issue 34 (helper branch splat-core); the Editor calls this signature.
            throw new System.NotImplementedException("place-splat is being built (issue 34).");
        }
    }
}
