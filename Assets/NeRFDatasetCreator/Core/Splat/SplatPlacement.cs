namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a trained Gaussian splat goes in the Unity scene it was captured from (<c>nerf-dataset place-splat</c>,
    /// issue 34): the 4×4 that maps every Gaussian centre of <see cref="PlyPath"/> to Unity world, and the same placement
    /// as a Unity Transform shows it (one negative scale component carries the reflection).
    /// </summary>
    public sealed class SplatPlacement
    {
        public SplatPlacement(string trainer, string plyPath, double[] objectToWorld, double[] position, double[] rotation, double[] scale, string camerasJsonPath, System.Collections.Generic.IReadOnlyList<string> notes)
        {
            Trainer = trainer;
            PlyPath = plyPath;
            ObjectToWorld = objectToWorld;
            Position = position;
            Rotation = rotation;
            Scale = scale;
            CamerasJsonPath = camerasJsonPath;
            Notes = notes ?? new string[0];
        }

        /// <summary>"3dgs", "nerfstudio" or "gsplat".</summary>
        public string Trainer { get; }

        /// <summary>The absolute path of the PLY placed.</summary>
        public string PlyPath { get; }

        /// <summary>x_unity = M·[x_ply, 1]: 16 numbers, row-major, in Unity's world.</summary>
        public double[] ObjectToWorld { get; }

        /// <summary>Transform.position (x, y, z), Unity world.</summary>
        public double[] Position { get; }

        /// <summary>Transform.rotation as a quaternion (x, y, z, w), Unity's convention.</summary>
        public double[] Rotation { get; }

        /// <summary>Transform.localScale (x, y, z); exactly one component is negative when the map reflects.</summary>
        public double[] Scale { get; }

        /// <summary>The 3DGS-format cameras.json written for the viewer's camera slider, or null when none was written.</summary>
        public string CamerasJsonPath { get; }

        /// <summary>What the user should know (a choice made, a file not written and why).</summary>
        public System.Collections.Generic.IReadOnlyList<string> Notes { get; }

        /// <summary>The rotation as the Inspector's Euler angles in degrees (Unity's z-x-y order), x y z.</summary>
        public double[] EulerDegrees { get; internal set; }

        /// <summary>The trainer's frame in one line (e.g. "nerfstudio's dataparser frame (...)").</summary>
        public string TrainerFrame { get; internal set; }

        /// <summary>x_output = TrainerToOutput·[x_ply, 1]: 16 numbers, row-major (evaluate --geometry uses the same map).</summary>
        public double[] TrainerToOutput { get; internal set; }

        /// <summary>x_unity = OutputToUnity·[x_output, 1]: the dataset's unity_frame, 16 numbers row-major.</summary>
        public double[] OutputToUnity { get; internal set; }

        /// <summary>Null when the dataset records unity_frame; otherwise what the output-to-Unity matrix was derived from.</summary>
        public string UnityFrameDerivedFrom { get; internal set; }

        /// <summary>The cameras.json aras-p's importer will read for this PLY (the first up from its folder), or null for none.</summary>
        public string ViewerCamerasJsonPath { get; internal set; }

        /// <summary>How many train cameras <see cref="CamerasJsonPath"/> holds (0 when none was written).</summary>
        public int CameraCount { get; internal set; }
    }
}
