using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One view of a capture plan: where the Unity camera goes, the matrix written for it, and the files it
    /// produces. <see cref="TransformMatrix"/> is the output camera-to-world matrix (Blender world, recentred on
    /// the target) that <c>transform_matrix</c> holds.
    /// </summary>
    [Serializable]
    public sealed class PlannedView
    {
        /// <param name="kinds">The kinds of file the view writes, colour first; one array is shared by a split's views.</param>
        public PlannedView(DatasetSplit split, int index, UnityPose pose, Matrix4x4d transformMatrix, IReadOnlyList<DatasetFileKind> kinds,
            ViewTime? time = null, ShutterMotion motion = null, IReadOnlyList<string> relitKeys = null)
        {
            RelitKeys = relitKeys ?? Array.Empty<string>();
            Motion = motion;
            Split = split;
            Index = index;
            Pose = pose;
            TransformMatrix = transformMatrix;
            if (kinds == null) throw new ArgumentNullException(nameof(kinds));
            _kinds = kinds as DatasetFileKind[] ?? new List<DatasetFileKind>(kinds).ToArray();
            Time = time;
        }

        // The kinds, not the files: a file's path follows from them (DatasetLayout), and a 300 000-view plan then holds
        // 300 000 objects rather than 1.2 million (no path strings, no file objects until asked for).
        readonly DatasetFileKind[] _kinds;

        /// <summary>When a dynamic capture renders this view (<see cref="TimePlanning"/>); null in a static capture.</summary>
        public ViewTime? Time { get; }

        public DatasetSplit Split { get; }

        /// <summary>Index within the split: the <c>i</c> of <c>r_i</c>.</summary>
        public int Index { get; }

        /// <summary>The capture camera's Transform position and rotation in the Unity scene.</summary>
        public UnityPose Pose { get; }

        public Matrix4x4d TransformMatrix { get; }

        /// <summary>Motion blur: the shutter interval's start and end poses (and content times); null without blur.</summary>
        public ShutterMotion Motion { get; }

        /// <summary>
        /// Relighting: the lighting conditions' keys (<see cref="LightingKeys"/>) whose files the view writes when its kinds
        /// include <see cref="DatasetFileKind.RelitPng"/>; one list shared by a split's views; empty without relighting.
        /// </summary>
        public IReadOnlyList<string> RelitKeys { get; }

        /// <summary>The files the view writes, colour first, one per relighting key for the relit kinds (made on each call).</summary>
        public IReadOnlyList<PlannedFile> Files
        {
            get
            {
                var files = new List<PlannedFile>(_kinds.Length);
                foreach (var kind in _kinds)
                {
                    if (kind == DatasetFileKind.RelitPng || kind == DatasetFileKind.RelitHdrExr)
                        foreach (var key in RelitKeys) files.Add(new PlannedFile(kind, DatasetLayout.RelitRelativePath(Split, Index, key, kind == DatasetFileKind.RelitHdrExr)));
                    else files.Add(new PlannedFile(kind, DatasetLayout.RelativePath(Split, Index, kind)));
                }
                return files;
            }
        }

        /// <summary><c>r_7</c>.</summary>
        public string Stem => DatasetLayout.Stem(Index);

        /// <summary><c>./train/r_7</c>, the <c>file_path</c> value.</summary>
        public string FramePath => DatasetLayout.FramePath(Split, Index);

        public bool Writes(DatasetFileKind kind)
        {
            for (var k = 0; k < _kinds.Length; k++)
                if (_kinds[k] == kind) return true;
            return false;
        }
    }
}
