using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Scene and animated cameras as <see cref="CapturePlan"/> sees them: the Unity poses the editor read
    /// (<see cref="CameraSourceSettings.SceneCameras"/>) become a split's cameras like imported ones, with a
    /// horizontal field of view as their only intrinsics. Their written matrices go through the dataset's
    /// normalisation exactly as a formation's (<see cref="BlenderConvention.CameraToWorld"/>).
    /// </summary>
    public static class SceneCameraPlanning
    {
        /// <summary>The <see cref="ImportedPoses.Format"/> of cameras read from the scene.</summary>
        public const string Format = "scene";

        /// <summary>The split's cameras, or null with a problem when the scene was not read or gave none.</summary>
        public static ImportedSplit Resolve(CameraSourceSettings source, string field, int width, int height, List<ValidationProblem> problems)
        {
            var pathField = field + (source.Kind == CameraSourceKind.SceneCameras ? ".parent" : ".camera");
            var cameras = source.SceneCameras;
            if (source.SceneProblem != null)
            {
                problems.Add(source.SceneProblem);
                return null;
            }
            if (cameras == null)
            {
                problems.Add(new ValidationProblem(field + ".kind", "\"" + CameraSourceSettings.KindName(source.Kind) + "\"",
                    "takes its cameras from a Unity scene, which only the Unity editor can read (nerf-dataset has no scene).",
                    "Plan and capture this config in Unity (window or batch mode), or give the split a formation or imported cameras."));
                return null;
            }
            if (cameras.Count == 0)
            {
                problems.Add(new ValidationProblem(pathField, source.ObjectPath,
                    source.Kind == CameraSourceKind.SceneCameras ? "has no active camera under it." : "gave no camera poses.",
                    "Give the parent of active Camera objects."));
                return null;
            }
            if (cameras.Count > DatasetSettings.MaxViews)
            {
                problems.Add(ValidationProblem.OutsideRange(field, cameras.Count, 1, DatasetSettings.MaxViews));
                return null;
            }
            var imported = cameras.Select(c => new ImportedCamera(c.Name, null, BlenderConvention.CameraToWorld(c.Pose), c.Pose,
                ImportedIntrinsics.AngleOnly(HorizontalFov(c.VerticalFovDegrees, width, height)))).ToList();
            // Normalisation null: the "file" world is the raw output world, so PosePlacement.ToOutput applies the
            // dataset's normalisation to them as to a formation's poses.
            return new ImportedSplit(new ImportedPoses(source.ObjectPath, Format, imported, null, source.SceneWarnings), imported, field);
        }

        /// <summary><c>camera_angle_x</c> (radians) of a Unity vertical field of view at W × H.</summary>
        public static double HorizontalFov(double verticalFovDegrees, int width, int height) =>
            width > 0 && height > 0 ? 2 * Math.Atan(Math.Tan(verticalFovDegrees * Math.PI / 360) * width / height) : 0;

        /// <summary>"60° (Shots/A, Shots/B), 40° (Shots/C)" — the vertical fields of view and who has them, for messages.</summary>
        public static string DescribeFovs(IReadOnlyList<ImportedCamera> cameras)
        {
            var groups = cameras.GroupBy(c => Math.Round(c.Intrinsics?.CameraAngleX ?? 0, 9)).ToList();
            return string.Join(", ", groups.Select(g =>
                (g.Key * 180 / Math.PI).ToString("0.###", CultureInfo.InvariantCulture) + "° across (" +
                string.Join(", ", g.Take(3).Select(c => c.Name)) + (g.Count() > 3 ? ", …" : "") + ")"));
        }
    }
}
