namespace NerfDatasetCreator
{
    /// <summary>Identifies the software that wrote a dataset, in its <c>dataset_config.json</c>.</summary>
    public static class PluginInfo
    {
        public const string Name = "NeRF Dataset Creator";

        /// <summary>Must equal package.json's "version" (a test checks it).</summary>
        public const string Version = "0.2.0";
    }
}
