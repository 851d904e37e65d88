using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Where a split's cameras come from.</summary>
    public enum CameraSourceKind
    {
        /// <summary>The split's formation around the target (the default).</summary>
        Formation,

        /// <summary>The cameras of an existing transforms file or COLMAP text model (<see cref="CameraSourceSettings.Path"/>).</summary>
        ImportedPoses,

        /// <summary>Every camera under a scene object (<see cref="CameraSourceSettings.ObjectPath"/>), one view each.</summary>
        SceneCameras,

        /// <summary>One scene camera driven by an Animator, Animation or Timeline, sampled over its time range (<see cref="AnimatedCameraSampling"/>).</summary>
        AnimatedCamera,

        /// <summary>Inside-out: cameras sampled in a scene box (<see cref="CameraSourceSettings.ObjectPath"/>), looking outwards, never inside obstacles (<see cref="VolumeSampling"/>).</summary>
        Volume,
    }

    /// <summary>
    /// A split's camera source. With any source but the formation the split has one view per source camera (its
    /// count and formation are not used). Imported cameras are read by Core; scene and animated cameras are read by
    /// the Unity editor into <see cref="SceneCameras"/> before planning.
    /// </summary>
    [Serializable]
    public sealed class CameraSourceSettings
    {
        public CameraSourceKind Kind = CameraSourceKind.Formation;

        /// <summary>
        /// A transforms JSON file (Blender / nerfstudio / instant-ngp / this plugin) or a COLMAP text model folder;
        /// relative paths are relative to the working directory (the Unity project folder in the editor).
        /// </summary>
        public string Path = "";

        /// <summary>Only the cameras the file puts in this split (<c>train</c>, <c>val</c>, <c>test</c>); empty for all of them.</summary>
        public string FileSplit = "";

        /// <summary>
        /// Use the file's field of view and image size for the whole dataset instead of the camera settings (the
        /// dataset has one camera, so every imported split that asks must agree).
        /// </summary>
        public bool UseFileIntrinsics;

        /// <summary>
        /// Scene and animated cameras: the hierarchy path of the parent whose cameras are used (config
        /// <c>"parent"</c>) or of the animated camera (config <c>"camera"</c>).
        /// </summary>
        public string ObjectPath = "";

        /// <summary>
        /// Scene and animated cameras: render with the cameras' own field of view (a physical camera's framing at the
        /// dataset's image size) instead of the Camera step's. They must agree: a dataset has one camera.
        /// </summary>
        public bool UseCameraIntrinsics = true;

        /// <summary>Animated camera: views spread evenly over the time range, ends included (used when <see cref="FrameStep"/> is 0).</summary>
        public int Samples = 100;

        /// <summary>Animated camera: every k-th frame of the range instead of <see cref="Samples"/>; 0 for even samples.</summary>
        public int FrameStep;

        /// <summary>Animated camera: frames per second for <see cref="FrameStep"/>; 0 for the clip's own (a Timeline's, or 60).</summary>
        public double FrameRate;

        /// <summary>Animated camera: the sampled range in seconds; <see cref="End"/> ≤ 0 means the end of the longest clip or Timeline.</summary>
        public double Start;
        public double End;

        /// <summary>Volume: where the cameras look.</summary>
        public VolumeLook Look = VolumeLook.Ring;

        /// <summary>Volume: cameras per cubic unit of the box; 0 to use the split's count.</summary>
        public double Density;

        /// <summary>Volume, <see cref="VolumeLook.Forward"/>: the largest tilt from the box's +Z, in degrees.</summary>
        public double JitterDegrees = 10;

        /// <summary>Volume, <see cref="VolumeLook.Path"/>: the hierarchy path of the object whose children, in order, are the waypoints.</summary>
        public string PathObject = "";

        /// <summary>Volume: the least distance, in Unity units, from a camera to an obstacle box (keeps the near clip plane out of walls).</summary>
        public double Clearance = 0.25;

        /// <summary>
        /// The box and the obstacles the Unity editor read for a volume source; null until it looked (the headless tool
        /// never does, and refuses such a split). Not saved.
        /// </summary>
        [NonSerialized] public VolumeScene Volume;

        /// <summary>
        /// The cameras the Unity editor found for a scene or animated source, in order; null until it looked (the
        /// headless tool never does, and refuses such a split). Not saved: the scene is read again at every plan.
        /// </summary>
        [NonSerialized] public IReadOnlyList<SceneCamera> SceneCameras;

        /// <summary>Why the Unity editor could not read the source's cameras (an object not found…), reported instead of them; null when it could.</summary>
        [NonSerialized] public ValidationProblem SceneProblem;

        /// <summary>What the Unity editor read but does not reproduce (a Cinemachine camera's damping…), warned about when planning; null for none.</summary>
        [NonSerialized] public IReadOnlyList<ValidationProblem> SceneWarnings;

        public bool IsImported => Kind == CameraSourceKind.ImportedPoses;

        public bool IsFormation => Kind == CameraSourceKind.Formation;

        /// <summary>Cameras the Unity editor reads from the scene (scene cameras, an animated camera).</summary>
        public bool IsFromScene => Kind == CameraSourceKind.SceneCameras || Kind == CameraSourceKind.AnimatedCamera;

        /// <summary>Inside-out cameras sampled in a scene box.</summary>
        public bool IsVolume => Kind == CameraSourceKind.Volume;

        /// <summary>Whether the source's own intrinsics replace the Camera step's.</summary>
        public bool UsesSourceIntrinsics => IsImported ? UseFileIntrinsics : IsFromScene && UseCameraIntrinsics;

        public CameraSourceSettings Clone() => (CameraSourceSettings)MemberwiseClone();

        static readonly string[] Names = { "formation", "imported", "sceneCameras", "animatedCamera", "volume" };

        /// <summary>The config-file names of the kinds.</summary>
        public static string KindName(CameraSourceKind kind) => Names[(int)kind];

        public static bool TryParseKind(string name, out CameraSourceKind kind)
        {
            for (var i = 0; i < Names.Length; i++)
                if (string.Equals(name, Names[i], StringComparison.OrdinalIgnoreCase))
                {
                    kind = (CameraSourceKind)i;
                    return true;
                }
            kind = CameraSourceKind.Formation;
            return false;
        }

        /// <summary>Problems of the settings alone (the file or the scene is checked when planning).</summary>
        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix)
        {
            var problems = new List<ValidationProblem>();
            if (IsImported)
            {
                if (string.IsNullOrWhiteSpace(Path))
                    problems.Add(new ValidationProblem(fieldPrefix + ".path", "\"\"", "is empty; imported cameras need a file.",
                        "Give a transforms JSON file (e.g. nerf_synthetic's transforms_test.json) or a COLMAP model folder (sparse/0)."));
                if (!string.IsNullOrEmpty(FileSplit) && !((IList<string>)DatasetSplits.Names).Contains(FileSplit))
                    problems.Add(new ValidationProblem(fieldPrefix + ".fileSplit", "\"" + FileSplit + "\"", "is not a split name.",
                        "Use \"train\", \"val\", \"test\", or \"\" for every camera of the file."));
            }
            else if (Kind == CameraSourceKind.SceneCameras && string.IsNullOrWhiteSpace(ObjectPath))
                problems.Add(new ValidationProblem(fieldPrefix + ".parent", "\"\"", "is empty; scene cameras need the object they are under.",
                    "Give the hierarchy path of the parent of your cameras, e.g. \"Shots\" or \"Set/Shots\"."));
            else if (Kind == CameraSourceKind.AnimatedCamera)
            {
                if (string.IsNullOrWhiteSpace(ObjectPath))
                    problems.Add(new ValidationProblem(fieldPrefix + ".camera", "\"\"", "is empty; an animated camera source needs its camera.",
                        "Give the hierarchy path of the animated camera, e.g. \"Flythrough/Camera\"."));
                problems.AddRange(AnimatedCameraSampling.Validate(fieldPrefix, Samples, FrameStep, FrameRate, Start, End));
            }
            else if (IsVolume)
                problems.AddRange(VolumePlanning.Validate(this, fieldPrefix));
            return problems;
        }
    }
}
