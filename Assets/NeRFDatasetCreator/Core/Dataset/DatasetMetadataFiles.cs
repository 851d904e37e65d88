namespace NerfDatasetCreator
{
    /// <summary>
    /// The JSON files of a dataset — the three transforms files (always all three, even for an empty split),
    /// dataset_config.json and eval_protocol.json (<see cref="EvalProtocolFile"/>, from the settings' background and
    /// <see cref="DatasetSettings.EvaluationBackground"/>). A capture writes them after its images, so a dataset never
    /// names an image that is not there.
    /// </summary>
    public static class DatasetMetadataFiles
    {
        /// <param name="wholeDataset">False for one shard of a sharded capture: its views are a share of the plan's, so it writes no
        /// sparse-view split files (their indices are the whole dataset's; <c>nerf-dataset splits</c> writes them after merge).</param>
        public static void Write(DatasetWriteSession session, CapturePlan plan, Provenance provenance, PointCloudRecord pointCloud = null,
            Newtonsoft.Json.Linq.JObject geometry = null, bool wholeDataset = true)
        {
            foreach (var split in DatasetSplits.All)
            {
                // Streamed: the text of a large plan's file is never held in memory whole.
                var s = split;
                session.WriteText(DatasetLayout.TransformsFileName(split), text => BlenderTransformsWriter.Write(plan, s, text));
            }
            // The config's sparseViews (none by default): splits/sparse_<n>.json from the planned poses.
            if (wholeDataset) SparseSplitFiles.Write(session, plan);
            session.WriteText(DatasetLayout.ConfigFileName, DatasetConfig.Write(plan, provenance, pointCloud, geometry));
            session.WriteText(EvalProtocolFile.FileName, EvalProtocolFile.Text(EvalProtocol.For(plan.Settings.Background, plan.Settings.EvaluationBackground)));
        }
    }
}
