namespace NerfDatasetCreator
{
    /// <summary>
    /// The conversion from Unity's world (left-handed, +Y up; cameras look along +Z) to the output convention of
    /// nerf_synthetic: Blender's world (right-handed, +Z up), (x, y, z)_out = (x, z, y)_Unity, and OpenGL camera
    /// axes (+X right, +Y up, looking along −Z). With P the Y/Z swap, the camera-to-world matrix written is
    /// M = P₄·C, C being Unity's <c>cameraToWorldMatrix</c>: columns (P·right, P·up, −P·forward, P·position).
    /// det P = −1 cancels the −1 of Unity's left-handed frame, so M's rotation is proper (det +1); nothing is
    /// mirrored, the same physical directions are only relabelled.
    /// </summary>
    public static class BlenderConvention
    {
        /// <summary>A point or direction from Unity's world into the output world: (x, z, y).</summary>
        public static Vector3d FromUnity(Vector3d unity) => new Vector3d(unity.X, unity.Z, unity.Y);

        /// <summary>A point or direction from the output world into Unity's world: (x, z, y) again, as P = P⁻¹.</summary>
        public static Vector3d ToUnity(Vector3d output) => new Vector3d(output.X, output.Z, output.Y);

        /// <summary>The output camera-to-world matrix (<c>transform_matrix</c>) for a Unity camera pose.</summary>
        public static Matrix4x4d CameraToWorld(UnityPose pose)
        {
            var rotation = pose.Rotation;
            return Matrix4x4d.FromColumns(
                FromUnity(rotation.Right),
                FromUnity(rotation.Up),
                -FromUnity(rotation.Forward),
                FromUnity(pose.Position));
        }

        /// <summary>
        /// The Unity pose of an output camera-to-world matrix (the inverse of <see cref="CameraToWorld"/>), for
        /// placing a camera where an existing dataset's frame was. The rotation part must be orthonormal.
        /// </summary>
        public static UnityPose ToUnityPose(Matrix4x4d cameraToWorld)
        {
            var right = ToUnity(cameraToWorld.Column(0));
            var up = ToUnity(cameraToWorld.Column(1));
            var forward = -ToUnity(cameraToWorld.Column(2));
            return new UnityPose(ToUnity(cameraToWorld.Translation), Quaterniond.FromBasis(right, up, forward));
        }
    }
}
