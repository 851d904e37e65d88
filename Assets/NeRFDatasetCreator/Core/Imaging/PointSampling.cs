using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The rule for depth and normals, which must never be averaged across an edge: each output pixel takes ONE
    /// rendered sample of its k×k block — the one nearest the block's centre that hit a surface; if none did, the
    /// pixel is background. For odd k that is the centre sample whenever it hit; for even k the four central
    /// samples tie and are tried in the order lower-left, lower-right, upper-left, upper-right. Depth reads the four
    /// together (DepthEncoding.Sample: their harmonic mean on one smooth surface, the nearest across a step).
    /// </summary>
    internal static class PointSampling
    {
        /// <summary>
        /// Pixel offsets from a block's lower-left sample, in trial order (k² entries). Plain arrays, not
        /// stackalloc spans: one tiny allocation per frame, and no reliance on Span in Unity's .NET Framework profile.
        /// </summary>
        internal static int[] Order(int k, int rowPixels)
        {
            var offsets = new int[k * k];
            var distance = new int[k * k];
            double centre = (k - 1) / 2.0;
            int n = 0;
            for (int dy = 0; dy < k; dy++)
            for (int dx = 0; dx < k; dx++)
            {
                // Four times the squared distance is an integer even for the half-integer centre of an even k.
                int d = (int)Math.Round(4 * ((dx - centre) * (dx - centre) + (dy - centre) * (dy - centre)));
                int offset = dy * rowPixels + dx;
                int i = n++;
                // Insertion sort keeps row-major order among equal distances (stable).
                while (i > 0 && distance[i - 1] > d)
                {
                    distance[i] = distance[i - 1];
                    offsets[i] = offsets[i - 1];
                    i--;
                }
                distance[i] = d;
                offsets[i] = offset;
            }
            return offsets;
        }
    }
}
