using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A sparse COLMAP model as both writers (<see cref="ColmapTextWriter"/>, <see cref="ColmapBinaryWriter"/>) emit it:
    /// one shared camera (id 1: PINHOLE, or the dataset's lens model), the images (id = index + 1, in frame order) with their poses and names, the
    /// points (id = index + 1) and, when visibility was computed, the observations. Image i's POINTS2D are the
    /// projections of <see cref="Observations"/>[i] (point indices, ascending), recomputed with
    /// <see cref="ColmapPose.Project(Vector3d, CameraIntrinsics, LensDistortion, out double, out double)"/> (through <see cref="Lens"/>) when written rather than stored: 16 bytes per observation saved on models of
    /// millions of observations. Point p's TRACK is <see cref="TrackImage"/>/<see cref="TrackPoint2D"/> from
    /// <see cref="TrackStart"/>[p] to [p + 1], images ascending.
    /// </summary>
    public sealed class ColmapModel
    {
        public ColmapModel(CameraIntrinsics camera, IReadOnlyList<string> names, IReadOnlyList<ColmapPose> poses,
            IReadOnlyList<CloudPoint> points, int[][] observations = null, LensDistortion lens = null)
        {
            Lens = lens;
            Camera = camera ?? throw new ArgumentNullException(nameof(camera));
            Names = names ?? throw new ArgumentNullException(nameof(names));
            Poses = poses ?? throw new ArgumentNullException(nameof(poses));
            Points = points ?? Array.Empty<CloudPoint>();
            if (poses.Count != names.Count) throw new ArgumentException("One pose per image name is needed.", nameof(poses));
            Observations = observations ?? new int[names.Count][];
            if (Observations.Length != names.Count) throw new ArgumentException("One observation list per image is needed.", nameof(observations));
            for (var i = 0; i < Observations.Length; i++) Observations[i] = Observations[i] ?? Array.Empty<int>();

            // Tracks: count, prefix-sum, fill. Images are visited in order, so each track lists its images ascending.
            TrackStart = new int[Points.Count + 1];
            foreach (var list in Observations)
                foreach (var p in list)
                {
                    if ((uint)p >= (uint)Points.Count) throw new ArgumentException("An observation names point " + p + " of " + Points.Count + ".", nameof(observations));
                    TrackStart[p + 1]++;
                }
            for (var p = 0; p < Points.Count; p++) TrackStart[p + 1] += TrackStart[p];
            ObservationCount = TrackStart[Points.Count];
            TrackImage = new int[ObservationCount];
            TrackPoint2D = new int[ObservationCount];
            var next = (int[])TrackStart.Clone();
            for (var i = 0; i < Observations.Length; i++)
            {
                var list = Observations[i];
                for (var k = 0; k < list.Length; k++)
                {
                    var slot = next[list[k]]++;
                    TrackImage[slot] = i;
                    TrackPoint2D[slot] = k;
                }
            }
        }

        public CameraIntrinsics Camera { get; }

        /// <summary>The lens the images were taken through (the written camera's distortion), or null for PINHOLE: POINTS2D are projected through it.</summary>
        public LensDistortion Lens { get; }
        public IReadOnlyList<string> Names { get; }
        public IReadOnlyList<ColmapPose> Poses { get; }
        public IReadOnlyList<CloudPoint> Points { get; }

        /// <summary>Per image (0-based), the indices of the points it sees, ascending: its POINTS2D in order.</summary>
        public int[][] Observations { get; }

        public int[] TrackStart { get; }

        /// <summary>0-based image index of each track element (the file holds index + 1).</summary>
        public int[] TrackImage { get; }

        /// <summary>Index into that image's POINTS2D of each track element.</summary>
        public int[] TrackPoint2D { get; }

        public int ObservationCount { get; }

        public int TrackLength(int point) => TrackStart[point + 1] - TrackStart[point];

        /// <summary>
        /// COLMAP's ERROR of a point: the mean reprojection error over its track
        /// (<c>Reconstruction::UpdatePoint3DErrors</c>, src/colmap/scene/reconstruction.cc lines 959–974), 0 without a
        /// track. Every 2D point here is the exact projection of its 3D point with the written pose, so it is 0; what
        /// COLMAP recomputes from the files differs only by double rounding (the tests check it is below 1e-9 px).
        /// </summary>
        public double Error(int point) => 0;

        public double MeanTrackLength => Points.Count == 0 ? 0 : (double)ObservationCount / Points.Count;

        public double MeanObservationsPerImage => Names.Count == 0 ? 0 : (double)ObservationCount / Names.Count;
    }
}
