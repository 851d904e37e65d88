using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How <c>convert --to colmap</c> writes the sparse model: text (<c>*.txt</c>, the default) or binary
    /// (<c>*.bin</c>, <c>--binary</c>); how many of the dataset's surface points it uses (<c>--points N</c>: the first N
    /// of <c>points3d.ply</c>, whose order is the sampler's random draw, so any prefix is a uniform sample; null = all);
    /// and the minimum track length a point needs to be kept when tracks are computed (<c>--min-track N</c>, default 2:
    /// a COLMAP point is triangulated from at least two views). See <see cref="ColmapVisibility"/>.
    /// </summary>
    public sealed class ColmapOptions
    {
        public const int DefaultMinTrackLength = 2;

        public ColmapOptions(bool binary = false, int? maxPoints = null, int minTrackLength = DefaultMinTrackLength)
        {
            InvalidParameterException.ThrowIfAny(
                maxPoints.HasValue && maxPoints.Value < 1
                    ? new ValidationProblem("--points", maxPoints.Value.ToString(CultureInfo.InvariantCulture), "must be at least 1.", "Give how many points of points3d.ply to use, or leave --points out for all.")
                    : null,
                minTrackLength < 0
                    ? new ValidationProblem("--min-track", minTrackLength.ToString(CultureInfo.InvariantCulture), "must be 0 or more.", "Give the fewest images a point must be seen in (0 keeps every point).")
                    : null);
            Binary = binary;
            MaxPoints = maxPoints;
            MinTrackLength = minTrackLength;
        }

        public static readonly ColmapOptions Default = new ColmapOptions();

        /// <summary>Write <c>cameras.bin</c>, <c>images.bin</c>, <c>points3D.bin</c> instead of the text files.</summary>
        public bool Binary { get; }

        /// <summary>Use at most this many points of the cloud (its first ones); null = all.</summary>
        public int? MaxPoints { get; }

        /// <summary>With tracks, points seen in fewer images are left out of the model (0 keeps all).</summary>
        public int MinTrackLength { get; }
    }
}
