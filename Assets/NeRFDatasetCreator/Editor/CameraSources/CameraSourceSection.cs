using System.IO;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A split's camera source in the Rig step: its formation, the cameras of an existing dataset (a transforms JSON
    /// file or a COLMAP text model folder), the cameras under a scene object, an animated scene camera sampled over
    /// its clip, or cameras sampled inside a box looking out (see <see cref="CameraSourceSettings"/>). Scene objects are stored by hierarchy path, like the target.
    /// </summary>
    static class CameraSourceSection
    {
        static readonly string[] KindLabels = { "Formation", "Imported cameras", "Scene cameras", "Animated camera", "Inside-out volume" };
        static readonly string[] LookLabels = { "Horizontal ring", "Full sphere", "Forward with jitter", "Along a path (waypoints)" };
        static readonly string[] FileSplitLabels = { "All cameras", "train", "val", "test" };
        static readonly string[] FileSplitValues = { "", "train", "val", "test" };
        static readonly string[] SamplingLabels = { "Views spread evenly", "Every k-th frame" };

        /// <summary>Draws the source; true when the split's cameras do not come from its formation (then count and formation are not used).</summary>
        public static bool Draw(WindowContext c, DatasetSplit split)
        {
            var settings = c.Settings.Split(split);
            var source = settings.Source ?? (settings.Source = new CameraSourceSettings());
            var field = WindowFields.SplitField(split, "source");
            source.Kind = (CameraSourceKind)EditorGUILayout.Popup("Cameras", (int)source.Kind, KindLabels);
            switch (source.Kind)
            {
                case CameraSourceKind.ImportedPoses:
                    DrawImported(c, split, source);
                    break;
                case CameraSourceKind.SceneCameras:
                    source.ObjectPath = PickObject(c, "Parent of the cameras", "Every active camera at and below this object is one view, in hierarchy order.", source.ObjectPath, typeof(GameObject));
                    ValidationMessages.For(c, field + ".parent");
                    DrawUseCameraIntrinsics(source);
                    break;
                case CameraSourceKind.AnimatedCamera:
                    DrawAnimated(c, source, field);
                    break;
                case CameraSourceKind.Volume:
                    DrawVolume(c, split, source, field);
                    break;
                default:
                    return false;
            }
            ValidationMessages.For(c, field);
            return true;
        }

        static void DrawImported(WindowContext c, DatasetSplit split, CameraSourceSettings source)
        {
            EditorGUILayout.BeginHorizontal();
            source.Path = EditorGUILayout.TextField(new GUIContent("File or model folder", "A transforms JSON (Blender, nerfstudio, instant-ngp, this plugin) or a COLMAP text model folder such as sparse/0; relative to the project folder."), source.Path ?? "");
            // The dialog runs after this GUI event, when `source` (part of this event's working copy) is gone: the
            // window stores the pick itself (PickedPaths.WithImportedCameras), as it does for the output folder.
            var start = PickStart(source.Path);
            if (GUILayout.Button("File…", GUILayout.Width(48))) c.Later(() => c.PickCameras?.Invoke(split, start, false));
            if (GUILayout.Button("Folder…", GUILayout.Width(60))) c.Later(() => c.PickCameras?.Invoke(split, start, true));
            EditorGUILayout.EndHorizontal();
            var index = System.Array.IndexOf(FileSplitValues, source.FileSplit ?? "");
            index = EditorGUILayout.Popup("Cameras of the file", index < 0 ? 0 : index, FileSplitLabels);
            source.FileSplit = FileSplitValues[index];
            source.UseFileIntrinsics = EditorGUILayout.Toggle(new GUIContent("Use the file's camera", "Render with the file's field of view and image size instead of the Camera step's."), source.UseFileIntrinsics);
        }

        static void DrawAnimated(WindowContext c, CameraSourceSettings source, string field)
        {
            source.ObjectPath = PickObject(c, "Animated camera", "A camera moved by an Animator, an Animation or a Timeline under its root object; sampled on a copy, your scene does not move.", source.ObjectPath, typeof(Camera));
            ValidationMessages.For(c, field + ".camera");
            var stepped = EditorGUILayout.Popup("Sampling", source.FrameStep > 0 ? 1 : 0, SamplingLabels) == 1;
            if (stepped)
            {
                source.FrameStep = Mathf.Max(1, EditorGUILayout.IntField(new GUIContent("Frame step", "Every k-th frame from the start."), Mathf.Max(1, source.FrameStep)));
                source.FrameRate = EditorGUILayout.DoubleField(new GUIContent("Frame rate", "Frames per second; 0 for the clip's (a Timeline's, else 60)."), source.FrameRate);
                ValidationMessages.For(c, field + ".frameStep");
                ValidationMessages.For(c, field + ".frameRate");
            }
            else
            {
                source.FrameStep = 0;
                source.Samples = EditorGUILayout.IntField(new GUIContent("Views", "Spread evenly over the range, both ends included."), source.Samples);
                ValidationMessages.For(c, field + ".samples");
            }
            source.Start = EditorGUILayout.DoubleField(new GUIContent("Start (s)", "Time of the first sample."), source.Start);
            source.End = EditorGUILayout.DoubleField(new GUIContent("End (s)", "0 for the end of the longest clip or Timeline."), source.End);
            ValidationMessages.For(c, field + ".start");
            ValidationMessages.For(c, field + ".end");
            DrawUseCameraIntrinsics(source);
        }

        static void DrawVolume(WindowContext c, DatasetSplit split, CameraSourceSettings source, string field)
        {
            source.ObjectPath = PickObject(c, "Capture box", "An object whose Transform (position, rotation, scale) is the box the cameras are sampled in; e.g. a scaled empty.", source.ObjectPath, typeof(GameObject));
            ValidationMessages.For(c, field + ".box");
            source.Look = (VolumeLook)EditorGUILayout.Popup(new GUIContent("Look", "Where each camera looks: level at a random heading, any direction, along the box's blue (+Z) axis within the jitter, or placed along a path through waypoints looking forward."), (int)source.Look, LookLabels);
            if (source.Look == VolumeLook.Path)
            {
                source.PathObject = PickObject(c, "Waypoints", "An object whose children, in hierarchy order, are the path's waypoints; the cameras are spread evenly along a smooth curve through them.", source.PathObject, typeof(GameObject));
                ValidationMessages.For(c, field + ".waypoints");
            }
            if (source.Look == VolumeLook.Forward || source.Look == VolumeLook.Path)
            {
                source.JitterDegrees = EditorGUILayout.DoubleField(new GUIContent("Jitter (°)", source.Look == VolumeLook.Path ? "Largest tilt from the path's direction." : "Largest tilt from the box's +Z."), source.JitterDegrees);
                ValidationMessages.For(c, field + ".jitterDegrees");
            }
            if (source.Look != VolumeLook.Path)
            {
                source.Density = EditorGUILayout.DoubleField(new GUIContent("Density (per unit³)", "Cameras per cubic unit of the box; 0 to give the number of views."), source.Density);
                ValidationMessages.For(c, field + ".density");
            }
            if (source.Density <= 0 || source.Look == VolumeLook.Path)
            {
                var splitSettings = c.Settings.Split(split);
                splitSettings.Count = EditorGUILayout.IntField("Views", splitSettings.Count);
                ValidationMessages.For(c, WindowFields.SplitField(split, "count"));
            }
            source.Clearance = EditorGUILayout.DoubleField(new GUIContent("Clearance", "Least distance from a camera to a collider's box; keep it above the near clip plane."), source.Clearance);
            ValidationMessages.For(c, field + ".clearance");
            EditorGUILayout.HelpBox("Positions inside an enabled, non-trigger collider (box, sphere, capsule, convex mesh) grown by the clearance are rejected; the plan's warnings count them.", MessageType.None);
        }

        static void DrawUseCameraIntrinsics(CameraSourceSettings source) =>
            source.UseCameraIntrinsics = EditorGUILayout.Toggle(new GUIContent("Use the cameras' lens", "Render with the cameras' own field of view (a physical camera's framing at the image size) instead of the Camera step's; they must share it."), source.UseCameraIntrinsics);

        /// <summary>An object field for a scene object stored by hierarchy path; the path stays when its scene is closed.</summary>
        static string PickObject(WindowContext c, string label, string tooltip, string path, System.Type type)
        {
            var found = SceneObjects.Find(path);
            Object current = found == null ? null : type == typeof(GameObject) ? (Object)found : found.GetComponent(type);
            EditorGUI.BeginChangeCheck();
            var picked = EditorGUILayout.ObjectField(new GUIContent(label, tooltip), current, type, true);
            if (EditorGUI.EndChangeCheck())
            {
                if (picked != null && EditorUtility.IsPersistent(picked))
                    c.PickNotice = "'" + picked.name + "' is in an asset, not in the scene. Pick an object of the open scene.";
                else
                {
                    var go = picked is Component component ? component.gameObject : picked as GameObject;
                    return go == null ? "" : SceneObjectPath.Of(go);
                }
            }
            if (found == null && !string.IsNullOrWhiteSpace(path)) EditorGUILayout.LabelField(" ", "Not in the open scenes: " + path, EditorStyles.miniLabel);
            return path ?? "";
        }

        /// <summary>The folder a picker opens in: the current path's folder, or "" (the dialog's default).</summary>
        static string PickStart(string path)
        {
            try
            {
                return string.IsNullOrEmpty(path) ? "" : Path.GetDirectoryName(Path.GetFullPath(path));
            }
            catch (System.Exception e) when (e is System.ArgumentException || e is System.NotSupportedException || e is PathTooLongException)
            {
                return "";
            }
        }

        /// <summary>The dialog of the File… and Folder… buttons; null when cancelled.</summary>
        public static string ShowPicker(string start, bool folder) =>
            folder
                ? EditorUtility.OpenFolderPanel("COLMAP text model folder (cameras.txt, images.txt)", start, "")
                : EditorUtility.OpenFilePanel("Transforms file", start, "json");
    }
}
