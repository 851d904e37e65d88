namespace NerfDatasetCreator
{
    /// <summary>
    /// The JSON files of a dataset — the three transforms files (always all three, even for an empty split) and
    /// dataset_config.json. A capture writes them after its images, so a dataset never names an image that is not there.
    /// </summary>
    public static class DatasetMetadataFiles
    {
        public static void Write(DatasetWriteSession session, CapturePlan plan, Provenance provenance, PointCloudRecord pointCloud = null,
            Newtonsoft.Json.Linq.JObject geometry = null)
        {
            foreach (var split in DatasetSplits.All)
            {
                // Streamed: the text of a large plan's file is never held in memory whole.
                var s = split;
                session.WriteText(DatasetLayout.TransformsFileName(split), text => BlenderTransformsWriter.Write(plan, s, text));
            }
            // The config's sparseViews (none by default): splits/sparse_<n>.json from the planned poses.
            SparseSplitFiles.Write(session, plan);
            session.WriteText(DatasetLayout.ConfigFileName, DatasetConfig.Write(plan, provenance, pointCloud, geometry));
        }
    }
}
