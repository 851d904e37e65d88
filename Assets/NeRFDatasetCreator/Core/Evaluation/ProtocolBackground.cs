namespace NerfDatasetCreator
{
    /// <summary>
    /// The background a dataset is meant to be trained and scored on, as 8-bit sRGB: what exports for trainers that
    /// drop alpha composite the RGBA images over (<see cref="AlphaCompositing"/>). Today: the dataset's own solid colour
    /// when it has one, else white (nerf_synthetic's evaluation). Issue 35's <c>eval_protocol.json</c> is read here first
    /// once it exists, so every export follows the protocol through this one function.
    /// </summary>
    public static class ProtocolBackground
    {
        /// <summary>The protocol's background for the dataset in <paramref name="datasetRoot"/>: its name ("white", "black", "dataset") and colour.</summary>
        public static (string Name, byte R, byte G, byte B) For(string datasetRoot)
        {
            var settings = DatasetConfig.Read(datasetRoot).Config?.Background;
            if (settings != null && !settings.Transparent && !settings.Sky)
                return ("dataset", Byte(settings.R), Byte(settings.G), Byte(settings.B));
            return ("white", 255, 255, 255);
        }

        static byte Byte(double c) => (byte)System.Math.Round(System.Math.Max(0, System.Math.Min(1, c)) * 255);
    }
}
