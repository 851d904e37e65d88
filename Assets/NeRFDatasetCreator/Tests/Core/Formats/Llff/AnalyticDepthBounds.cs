using System;
using System.Collections.Generic;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The truth a near / far bound is checked against: for each view of an analytic dataset, the smallest and largest
    /// z-distance (output units) of the first surface seen through any pixel centre (i + ½, j + ½), traced through the
    /// analytic scene along NeRF's ray (whose camera-frame z component is −1, so its parameter is z).
    /// </summary>
    sealed class AnalyticDepthBounds
    {
        readonly Dictionary<string, (double Near, double Far)> _byImage = new Dictionary<string, (double, double)>();

        /// <summary>The callback for <see cref="AnalyticDataset.Options.OutputRays"/>.</summary>
        public void Record(PlannedView view, AnalyticScene scene, AnalyticDataset.RayOf rays, int width, int height)
        {
            double near = double.PositiveInfinity, far = 0;
            for (var j = 0; j < height; j++)
                for (var i = 0; i < width; i++)
                {
                    rays(i + 0.5, j + 0.5, out var o, out var d);
                    if (!scene.Trace(o, d, 0, out var t, out _, out _, out _)) continue;
                    near = Math.Min(near, t);
                    far = Math.Max(far, t);
                }
            lock (_byImage) _byImage[DatasetSplits.Name(view.Split) + "/r_" + view.Index + ".png"] = (near, far);
        }

        /// <summary>The bounds of the view whose image is <paramref name="imagePath"/> (e.g. <c>train/r_0.png</c>).</summary>
        public (double Near, double Far) Of(string imagePath) => _byImage[imagePath];
    }
}
