using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What places the views of one split of a plan, from which any view is made again on demand, in constant time
    /// and memory: a formation's direction i (<see cref="IIndexedFormation"/>), or imported camera i, at the time of
    /// slot i (<see cref="TimePlanning.SlotAt"/>), through the plan's normalisation. Immutable, so writer threads may
    /// ask for views at once. An imported split (a file, scene cameras, a volume's samples) holds its cameras anyway:
    /// they were read or sampled as a whole.
    /// </summary>
    sealed class PlanSplitViews
    {
        readonly int _cameras;
        readonly TimeRange _time;
        readonly IIndexedFormation _formation;
        readonly IReadOnlyList<UnityPose> _poses; // a formation that cannot give one direction alone (none built in)
        readonly ImportedSplit _imported;
        readonly Vector3d _centre;
        readonly double _distance;
        readonly SceneNormalisation _normalisation;
        readonly DatasetFileKind[] _kinds; // shared by the split's views
        readonly string[] _relitKeys; // relighting's condition keys, shared by the split's views
        readonly ShutterPlanning _shutter; // motion blur, or null

        public PlanSplitViews(DatasetSettings settings, DatasetSplit split, int offset, ImportedSplit imported, Vector3d centre, double distance,
            SceneNormalisation normalisation, TimeRange time)
        {
            var s = settings.Split(split);
            Split = split;
            Offset = offset;
            _time = time;
            _imported = imported;
            _centre = centre;
            _distance = distance;
            _normalisation = normalisation;
            _kinds = DatasetLayout.FileKinds(settings, split).ToArray();
            _relitKeys = LightingKeys.All(settings).ToArray();
            if (imported != null) _cameras = imported.Cameras.Count;
            else
            {
                // The checks CameraRig.Place makes, in its order: the rig, then the formation and its count.
                var formation = s.Formation.ToFormation(settings.Seed, DatasetSplits.Name(split));
                CameraRig.ThrowIfInvalid(centre, distance);
                _cameras = s.Count;
                if (formation is IIndexedFormation indexed)
                {
                    FormationMath.ThrowIfInvalid(formation, s.Count);
                    _formation = indexed;
                }
                else _poses = CameraRig.Place(formation, s.Count, centre, distance);
            }
            Count = TimePlanning.SlotCount(time, _cameras);
            _shutter = ShutterPlanning.ForSplit(settings, split, new CameraPoses(this), normalisation, time);
        }

        /// <summary>The split's cameras in order, each made when read: what the shutter's path motion needs of its neighbours.</summary>
        sealed class CameraPoses : IReadOnlyList<UnityPose>
        {
            readonly PlanSplitViews _split;

            public CameraPoses(PlanSplitViews split) => _split = split;

            public int Count => _split._cameras;

            public UnityPose this[int camera] => _split.CameraPose(camera);

            public IEnumerator<UnityPose> GetEnumerator()
            {
                for (var i = 0; i < Count; i++) yield return this[i];
            }

            System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() => GetEnumerator();
        }

        UnityPose CameraPose(int camera)
        {
            if (_imported != null) return _imported.Cameras[camera].Pose;
            return _formation != null ? LookAt.FromDirection(_centre, _formation.Direction(camera, _cameras), _distance) : _poses[camera];
        }

        public DatasetSplit Split { get; }

        /// <summary>The number of views before this split's in the plan.</summary>
        public int Offset { get; }

        /// <summary>The split's views: its cameras, times the steps of a multi-view capture.</summary>
        public int Count { get; }

        /// <summary>The Unity pose of view <paramref name="index"/> alone (the plan's warnings need no more).</summary>
        public UnityPose PoseAt(int index)
        {
            return CameraPose(TimePlanning.SlotAt(_time, Split, _cameras, index).Camera);
        }

        /// <summary>View <paramref name="index"/> of the split, made anew on each call.</summary>
        public PlannedView At(int index)
        {
            var slot = TimePlanning.SlotAt(_time, Split, _cameras, index);
            UnityPose pose;
            Matrix4x4d matrix;
            if (_imported != null)
            {
                var camera = _imported.Cameras[slot.Camera];
                pose = camera.Pose;
                matrix = PosePlacement.ToOutput(camera.FileCameraToWorld, _imported.Poses.Normalisation, _normalisation);
            }
            else
            {
                pose = CameraPose(slot.Camera);
                matrix = _normalisation.CameraToWorld(pose);
            }
            return new PlannedView(Split, slot.Index, pose, matrix, _kinds, slot.Time, _shutter?.Motion(slot.Camera, slot.Time, index), _relitKeys);
        }
    }
}
