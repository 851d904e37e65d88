using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A camera pose in Unity's world: what the capture camera's <c>Transform.position</c> and
    /// <c>Transform.rotation</c> are set to. The camera looks along its rotated +Z with its rotated +Y up.
    /// </summary>
    [Serializable]
    public readonly struct UnityPose
    {
        public UnityPose(Vector3d position, Quaterniond rotation)
        {
            Position = position;
            Rotation = rotation;
        }

        public Vector3d Position { get; }
        public Quaterniond Rotation { get; }

        /// <summary>
        /// Unity's <c>Camera.cameraToWorldMatrix</c> for this pose (unit scale): camera space follows OpenGL
        /// (forward is −Z), so the columns are (right, up, −forward, position). Its 3×3 part has det −1 because
        /// Unity's world is left-handed.
        /// </summary>
        public Matrix4x4d CameraToWorld =>
            Matrix4x4d.FromColumns(Rotation.Right, Rotation.Up, -Rotation.Forward, Position);
    }
}
