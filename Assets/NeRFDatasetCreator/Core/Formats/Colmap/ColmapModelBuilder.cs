using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The sparse model <c>convert --to colmap</c> writes: the poses of every frame, and the points — the dataset's own
    /// surface sample (at most <see cref="ColmapOptions.MaxPoints"/> of them) with exact tracks from the depth maps
    /// (<see cref="ColmapVisibility"/>), points seen in fewer than <see cref="ColmapOptions.MinTrackLength"/> images
    /// left out — or, when tracks cannot be known, the points with empty tracks and a warning saying why.
    /// </summary>
    public static class ColmapModelBuilder
    {
        /// <param name="surface">True when <paramref name="points"/> is the target's surface sample (ours); false for a stand-in cloud, which gets no tracks.</param>
        public static ColmapModel Build(ExportScene scene, IReadOnlyList<string> names, IReadOnlyList<CloudPoint> points, bool surface,
            ColmapOptions options, ICollection<ValidationProblem> warnings)
        {
            options = options ?? ColmapOptions.Default;
            var poses = scene.Frames.Select(f => ColmapPose.FromCameraToWorld(f.CameraToWorld)).ToList();
            points = points ?? Array.Empty<CloudPoint>();
            if (!surface)
                return new ColmapModel(scene.Intrinsics, names, poses, points);

            if (options.MaxPoints.HasValue)
            {
                if (options.MaxPoints.Value < points.Count) points = points.Take(options.MaxPoints.Value).ToList();
                else if (options.MaxPoints.Value > points.Count)
                    warnings?.Add(new ValidationProblem("--points", I(options.MaxPoints.Value),
                        "is more than the " + I(points.Count) + " points of " + PointCloudOwnership.FileName + "; all of them are used.",
                        "Capture with a larger pointCloudPoints for a denser model."));
            }
            if (!scene.HasDepth)
            {
                warnings?.Add(new ValidationProblem("points3D tracks", "empty",
                    "which images see a point is known only from depth maps, and " +
                    (scene.Frames.Any(f => f.DepthPath != null) ? "only some frames have one" : "this dataset has none") +
                    ": the points are written with empty tracks and the images with no 2D points (a model for 3DGS's initial cloud, but no depth supervision for gsplat and nothing for COLMAP's own tools).",
                    "Capture with depth (PNG) for every split to get exact tracks."));
                return new ColmapModel(scene.Intrinsics, names, poses, points);
            }

            var observations = ColmapVisibility.Compute(scene, points);
            var model = KeepTracked(scene.Intrinsics, names, poses, points, observations, options.MinTrackLength, scene.Lens);
            var untracked = Enumerable.Range(0, names.Count).Where(i => model.Observations[i].Length == 0).Select(i => names[i]).ToList();
            if (untracked.Count > 0)
                warnings?.Add(new ValidationProblem("images POINTS2D", untracked.Count + " image(s), e.g. " + untracked[0],
                    "observe none of the model's points; gsplat's depth loss (simple_trainer --depth_loss) fails with a KeyError on such an image.",
                    "Use more points (a larger pointCloudPoints) or a lower --min-track, or train without --depth_loss."));
            return model;
        }

        /// <summary>The model of the points seen in at least <paramref name="minTrackLength"/> images, renumbered in order.</summary>
        public static ColmapModel KeepTracked(CameraIntrinsics camera, IReadOnlyList<string> names, IReadOnlyList<ColmapPose> poses,
            IReadOnlyList<CloudPoint> points, int[][] observations, int minTrackLength, LensDistortion lens = null)
        {
            var counts = new int[points.Count];
            foreach (var list in observations)
                foreach (var p in list) counts[p]++;
            var newIndex = new int[points.Count];
            var kept = new List<CloudPoint>(points.Count);
            for (var p = 0; p < points.Count; p++)
            {
                if (counts[p] >= minTrackLength)
                {
                    newIndex[p] = kept.Count;
                    kept.Add(points[p]);
                }
                else newIndex[p] = -1;
            }
            var renumbered = new int[observations.Length][];
            for (var i = 0; i < observations.Length; i++)
            {
                var list = observations[i];
                var n = 0;
                foreach (var p in list) if (newIndex[p] >= 0) n++;
                var copy = new int[n];
                n = 0;
                foreach (var p in list) if (newIndex[p] >= 0) copy[n++] = newIndex[p]; // the map is increasing: order kept
                renumbered[i] = copy;
            }
            return new ColmapModel(camera, names, poses, kept, renumbered, lens);
        }

        static string I(int v) => v.ToString(CultureInfo.InvariantCulture);
    }
}
