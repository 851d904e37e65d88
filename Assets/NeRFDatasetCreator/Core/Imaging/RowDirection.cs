namespace NerfDatasetCreator
{
    /// <summary>
    /// Which image row an array starts with. PNG files and our PNG writer store the top row first. Unity's
    /// readbacks and the arrays Unity's ImageConversion.EncodeArrayTo* take are in texture order, bottom row first
    /// (an unflipped readback encodes upright; see Documentation~/pixels.md).
    /// </summary>
    public enum RowDirection
    {
        TopRowFirst,
        BottomRowFirst,
    }
}
