using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The inverse of the output convention for imported cameras. A file's camera-to-world matrix M_N lives in the
    /// normalised output world x_N = s·(x_raw − c) (<see cref="SceneNormalisation"/>), x_raw = (x, z, y) of the
    /// Unity point (<see cref="BlenderConvention"/>). Undoing both gives the Unity pose; re-exporting goes through
    /// the plan's normalisation. Rotations are never touched by a normalisation, so only the centre moves.
    /// </summary>
    public static class PosePlacement
    {
        /// <summary>A normalised-world point back into the raw output world: x_raw = c + x_N / s.</summary>
        public static Vector3d ToRawPoint(SceneNormalisation normalisation, Vector3d normalisedPoint) =>
            normalisation == null ? normalisedPoint : normalisation.Centre + normalisedPoint / normalisation.Scale;

        /// <summary>
        /// The Unity pose whose output matrix, under <paramref name="normalisation"/> (null: none), is
        /// <paramref name="fileCameraToWorld"/>. The rotation is first made exactly orthonormal keeping the viewing
        /// axis: float32 files (nerf_synthetic) are orthonormal only to ~1e-7, and a quaternion of a non-rotation
        /// would tilt the view by as much.
        /// </summary>
        public static UnityPose ToUnityPose(Matrix4x4d fileCameraToWorld, SceneNormalisation normalisation)
        {
            var back = fileCameraToWorld.Column(2).Normalized();
            var right = fileCameraToWorld.Column(0);
            right = (right - Vector3d.Dot(right, back) * back).Normalized();
            var up = Vector3d.Cross(back, right); // OpenGL camera: x × y = z
            var raw = Matrix4x4d.FromColumns(right, up, back, ToRawPoint(normalisation, fileCameraToWorld.Translation));
            return BlenderConvention.ToUnityPose(raw);
        }

        /// <summary>
        /// The matrix to write for an imported camera in a dataset normalised by <paramref name="output"/>: the file's
        /// own matrix, bit for bit, when both normalisations are the same (re-rendering a dataset's views writes its
        /// exact matrices), else the same rotation with the centre moved through the raw world.
        /// </summary>
        public static Matrix4x4d ToOutput(Matrix4x4d fileCameraToWorld, SceneNormalisation file, SceneNormalisation output)
        {
            var f = file ?? SceneNormalisation.Identity;
            var o = output ?? SceneNormalisation.Identity;
            if (f.Scale.Equals(o.Scale) && f.Centre.Equals(o.Centre)) return fileCameraToWorld;
            return o.ApplyToCameraToWorld(Matrix4x4d.FromColumns(fileCameraToWorld.Column(0), fileCameraToWorld.Column(1),
                fileCameraToWorld.Column(2), ToRawPoint(f, fileCameraToWorld.Translation)));
        }

        /// <summary>Why a matrix read from a file cannot be placed, or null (the checks of <see cref="DatasetValidator.PoseProblems"/>).</summary>
        public static string Problem(Matrix4x4d m)
        {
            var problems = DatasetValidator.PoseProblems(m);
            return problems.Count == 0 ? null : string.Join(" ", problems);
        }

        internal static string SplitFromName(string name)
        {
            if (string.IsNullOrEmpty(name)) return null;
            var n = name.Replace('\\', '/');
            if (n.StartsWith("./", StringComparison.Ordinal)) n = n.Substring(2);
            foreach (var split in DatasetSplits.Names)
                if (n.StartsWith(split + "/", StringComparison.Ordinal) || n.StartsWith(split + "_", StringComparison.Ordinal))
                    return split;
            return null;
        }
    }
}
