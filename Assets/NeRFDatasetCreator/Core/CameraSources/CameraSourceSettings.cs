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
    }

    /// <summary>
    /// A split's camera source. With <see cref="CameraSourceKind.ImportedPoses"/> the split has one view per camera
    /// of the file (its count and formation are not used) and the written matrices are the file's own whenever the
    /// dataset's normalisation is the file's (<see cref="PosePlacement.ToOutput"/>).
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

        public bool IsImported => Kind == CameraSourceKind.ImportedPoses;

        public CameraSourceSettings Clone() => (CameraSourceSettings)MemberwiseClone();

        /// <summary>The config-file names of the kinds.</summary>
        public static string KindName(CameraSourceKind kind) => kind == CameraSourceKind.ImportedPoses ? "imported" : "formation";

        public static bool TryParseKind(string name, out CameraSourceKind kind)
        {
            kind = CameraSourceKind.Formation;
            if (string.Equals(name, "formation", StringComparison.OrdinalIgnoreCase)) return true;
            if (!string.Equals(name, "imported", StringComparison.OrdinalIgnoreCase)) return false;
            kind = CameraSourceKind.ImportedPoses;
            return true;
        }

        /// <summary>Problems of the settings alone (the file itself is checked when planning).</summary>
        public IReadOnlyList<ValidationProblem> Validate(string fieldPrefix)
        {
            var problems = new List<ValidationProblem>();
            if (!IsImported) return problems;
            if (string.IsNullOrWhiteSpace(Path))
                problems.Add(new ValidationProblem(fieldPrefix + ".path", "\"\"", "is empty; imported cameras need a file.",
                    "Give a transforms JSON file (e.g. nerf_synthetic's transforms_test.json) or a COLMAP model folder (sparse/0)."));
            if (!string.IsNullOrEmpty(FileSplit) && !((IList<string>)DatasetSplits.Names).Contains(FileSplit))
                problems.Add(new ValidationProblem(fieldPrefix + ".fileSplit", "\"" + FileSplit + "\"", "is not a split name.",
                    "Use \"train\", \"val\", \"test\", or \"\" for every camera of the file."));
            return problems;
        }
    }
}
