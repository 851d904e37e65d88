namespace NerfDatasetCreator
{
    /// <summary>
    /// The JSON files of a dataset — the three transforms files (always all three, even for an empty split) and
    /// dataset_config.json. A capture writes them after its images, so a dataset never names an image that is not there.
    /// </summary>
    public static class DatasetMetadataFiles
    {
        public static void Write(DatasetWriteSession session, CapturePlan plan, Provenance provenance)
        {
            foreach (var split in DatasetSplits.All)
            {
                // Streamed: the text of a large plan's file is never held in memory whole.
                var path = session.PathOf(DatasetLayout.TransformsFileName(split));
                System.IO.Directory.CreateDirectory(System.IO.Path.GetDirectoryName(path));
                using (var file = JsonNumbers.CreateFile(path)) BlenderTransformsWriter.Write(plan, split, file);
            }
            session.WriteText(DatasetLayout.ConfigFileName, DatasetConfigWriter.Write(plan, provenance));
        }
    }
}
