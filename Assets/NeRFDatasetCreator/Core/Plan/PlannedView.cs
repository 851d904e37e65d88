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
        public PlannedView(DatasetSplit split, int index, UnityPose pose, Matrix4x4d transformMatrix, IReadOnlyList<PlannedFile> files,
            ViewTime? time = null)
        {
            Split = split;
            Index = index;
            Pose = pose;
            TransformMatrix = transformMatrix;
            Files = files;
            Time = time;
        }

        /// <summary>When a dynamic capture renders this view (<see cref="TimePlanning"/>); null in a static capture.</summary>
        public ViewTime? Time { get; }

        public DatasetSplit Split { get; }

        /// <summary>Index within the split: the <c>i</c> of <c>r_i</c>.</summary>
        public int Index { get; }

        /// <summary>The capture camera's Transform position and rotation in the Unity scene.</summary>
        public UnityPose Pose { get; }

        public Matrix4x4d TransformMatrix { get; }

        public IReadOnlyList<PlannedFile> Files { get; }

        /// <summary><c>r_7</c>.</summary>
        public string Stem => DatasetLayout.Stem(Index);

        /// <summary><c>./train/r_7</c>, the <c>file_path</c> value.</summary>
        public string FramePath => DatasetLayout.FramePath(Split, Index);

        public bool Writes(DatasetFileKind kind)
        {
            foreach (var f in Files)
                if (f.Kind == kind) return true;
            return false;
        }
    }
}
