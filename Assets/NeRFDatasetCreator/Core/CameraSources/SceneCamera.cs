using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A camera the Unity editor read from the scene for a split: its hierarchy path (with the sample time for an
    /// animated camera), where it is, and its vertical field of view at the dataset's image size (a physical
    /// camera's gate fit applied).
    /// </summary>
    [Serializable]
    public sealed class SceneCamera
    {
        public SceneCamera(string name, UnityPose pose, double verticalFovDegrees)
        {
            Name = name ?? "";
            Pose = pose;
            VerticalFovDegrees = verticalFovDegrees;
        }

        public string Name { get; }
        public UnityPose Pose { get; }

        /// <summary>Unity's <c>Camera.fieldOfView</c> that reproduces the camera's framing of a W × H image.</summary>
        public double VerticalFovDegrees { get; }
    }
}
