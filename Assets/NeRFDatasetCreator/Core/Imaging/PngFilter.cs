namespace NerfDatasetCreator
{
    /// <summary>
    /// Which PNG row filter (PNG spec §9) precedes DEFLATE. The five fixed types use one filter for every row;
    /// <see cref="Adaptive"/> picks one per row: with DeflateStream the filter whose output has the smallest sum of
    /// absolute values (the heuristic the PNG specification recommends and libpng uses); with the project's own
    /// encoders the one whose sampled residuals look cheapest to code (<see cref="PngWriter.DefaultFilter"/>).
    /// </summary>
    public enum PngFilter
    {
        None = 0,
        Sub = 1,
        Up = 2,
        Average = 3,
        Paeth = 4,

        /// <summary>Per row, the one of the five whose output looks cheapest to code.</summary>
        Adaptive = 5,
    }
}
