namespace NerfDatasetCreator
{
    /// <summary>
    /// A formation that gives any one of its directions without the others: a plan of 300 000 views then holds no
    /// list of poses, and regenerates each view when it is written (<see cref="PlannedViewList"/>).
    /// <see cref="ICameraFormation.Directions"/> of every built-in formation is this method in a loop, so both give
    /// the same numbers, bit for bit. The caller validates the formation and the count first (<see cref="ICameraFormation.Directions"/> does).
    /// </summary>
    public interface IIndexedFormation
    {
        /// <summary>Direction <paramref name="index"/> (0 ≤ index &lt; count) of <see cref="ICameraFormation.Directions"/>(<paramref name="count"/>).</summary>
        SphericalDirection Direction(int index, int count);
    }
}
