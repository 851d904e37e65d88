using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Unity reads render textures back bottom row first; PNG and EXR files store the top row first. The
    /// post-processing steps flip while they downsample; this is the flip alone, for data that needs nothing else.
    /// </summary>
    public static class RowOrder
    {
        /// <summary>Copies <paramref name="rows"/> rows of <paramref name="rowLength"/> elements in reverse row order.</summary>
        public static void FlipRows<T>(T[] source, T[] destination, int rowLength, int rows)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            if (destination == null) throw new ArgumentNullException(nameof(destination));
            if (ReferenceEquals(source, destination)) throw new ArgumentException("Flip into a different array; flipping in place would overwrite rows before they are read.", nameof(destination));
            long needed = (long)rowLength * rows;
            if (rowLength < 0 || rows < 0 || source.Length < needed || destination.Length < needed)
                throw new ArgumentException($"Both arrays need rowLength × rows = {needed} elements (source has {source.Length}, destination {destination.Length}).");
            for (int y = 0; y < rows; y++) Array.Copy(source, (rows - 1 - y) * rowLength, destination, y * rowLength, rowLength);
        }

        /// <summary>Index of the bottom source row of the k×k block that becomes output row <paramref name="outputRow"/> (top = 0).</summary>
        public static int SourceBlockRow(int outputRow, int outputHeight, int supersampling) =>
            (outputHeight - 1 - outputRow) * supersampling;
    }
}
