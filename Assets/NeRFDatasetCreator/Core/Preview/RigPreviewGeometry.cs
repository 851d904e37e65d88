using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Everything the Scene-view preview draws for one plan, computed once when the plan changes: per split a flat
    /// list of segment end points (<see cref="FrustumGeometry.WriteSegments"/> for each camera in order), and one
    /// marker per camera for picking, train first, then val, then test.
    /// </summary>
    public sealed class RigPreviewGeometry
    {
        static readonly PreviewSplit[] AllSplits = { PreviewSplit.Train, PreviewSplit.Val, PreviewSplit.Test };

        readonly Vector3d[][] segments;
        readonly PreviewMarker[] markers;

        RigPreviewGeometry(Vector3d[][] segments, PreviewMarker[] markers)
        {
            this.segments = segments;
            this.markers = markers;
        }

        /// <summary>Train, val and test, in drawing order.</summary>
        public static IReadOnlyList<PreviewSplit> Splits => AllSplits;

        public IReadOnlyList<PreviewMarker> Markers => markers;

        /// <summary>Segment end points of every camera of <paramref name="split"/>, <see cref="FrustumGeometry.PointsPerCamera"/> per camera.</summary>
        public IReadOnlyList<Vector3d> Segments(PreviewSplit split) => segments[(int)split];

        /// <summary>
        /// Builds the geometry. <paramref name="train"/>, <paramref name="val"/> and <paramref name="test"/> are the
        /// planned poses of each split in view order (null or empty for none).
        /// </summary>
        public static RigPreviewGeometry Build(IReadOnlyList<UnityPose> train, IReadOnlyList<UnityPose> val, IReadOnlyList<UnityPose> test,
            double verticalFovDegrees, double aspect, double frustumLength)
        {
            var bySplit = new[] { train ?? Array.Empty<UnityPose>(), val ?? Array.Empty<UnityPose>(), test ?? Array.Empty<UnityPose>() };
            var segments = new Vector3d[3][];
            var markers = new PreviewMarker[bySplit[0].Count + bySplit[1].Count + bySplit[2].Count];
            var m = 0;
            foreach (var split in AllSplits)
            {
                var poses = bySplit[(int)split];
                var points = new Vector3d[poses.Count * FrustumGeometry.PointsPerCamera];
                for (var i = 0; i < poses.Count; i++)
                {
                    FrustumGeometry.WriteSegments(poses[i], verticalFovDegrees, aspect, frustumLength, points, i * FrustumGeometry.PointsPerCamera);
                    markers[m++] = new PreviewMarker(split, i, poses[i].Position);
                }
                segments[(int)split] = points;
            }
            return new RigPreviewGeometry(segments, markers);
        }
    }
}
