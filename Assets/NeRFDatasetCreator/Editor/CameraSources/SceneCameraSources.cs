using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Reads the scene for every split whose cameras come from it, before Core plans: the cameras under a parent
    /// (<see cref="CameraSourceKind.SceneCameras"/>) or the samples of an animated camera
    /// (<see cref="AnimatedCameraSampler"/>), as <see cref="CameraSourceSettings.SceneCameras"/>, a volume's box and
    /// obstacles (<see cref="VolumeSource"/>) as <see cref="CameraSourceSettings.Volume"/>, or the reason they
    /// cannot be read as <see cref="CameraSourceSettings.SceneProblem"/>. The user's objects are only read.
    /// </summary>
    public static class SceneCameraSources
    {
        /// <summary>
        /// Fills the scene sources of <paramref name="settings"/>, a copy the caller owns (its splits' sources are changed).
        /// With <paramref name="sampleAnimations"/> false (the window's 10 Hz preview) an animated camera is not sampled
        /// — that copies its root or, for Cinemachine, the whole scene — but given the last samples of a check
        /// (<see cref="AnimatedCameraSampler.LastSampled"/>); returns true when any of those is stale or missing.
        /// </summary>
        public static bool Resolve(DatasetSettings settings, bool sampleAnimations = true)
        {
            var stale = false;
            foreach (var split in DatasetSplits.All)
            {
                var source = settings.Split(split)?.Source;
                var field = "splits." + DatasetSplits.Name(split) + ".source";
                if (source != null && source.IsVolume)
                {
                    source.Volume = VolumeSource.Read(source.ObjectPath, field, out source.SceneProblem, source.Look == VolumeLook.Path ? source.PathObject : null);
                    continue;
                }
                if (source == null || !source.IsFromScene) continue;
                source.SceneCameras = null;
                source.SceneProblem = null;
                source.SceneWarnings = null;
                if (source.Kind == CameraSourceKind.SceneCameras)
                    source.SceneCameras = UnderParent(source.ObjectPath, settings.Width, settings.Height, field, out source.SceneProblem);
                else if (sampleAnimations)
                    source.SceneCameras = AnimatedCameraSampler.Sample(source, settings.Width, settings.Height, field, out source.SceneProblem, out source.SceneWarnings);
                else
                {
                    source.SceneCameras = AnimatedCameraSampler.LastSampled(source, settings.Width, settings.Height, out var old, out source.SceneWarnings);
                    stale |= old;
                }
            }
            return stale;
        }

        /// <summary>
        /// The cameras on active objects at and below the object at <paramref name="parentPath"/>, in hierarchy order
        /// (<c>GetComponentsInChildren(includeInactive: false)</c>, which searches the object itself and its children
        /// depth first and skips inactive GameObjects — docs: Component.GetComponentsInChildren). A disabled Camera
        /// component still counts: shot cameras are often disabled so they do not render to the Game view.
        /// </summary>
        public static List<SceneCamera> UnderParent(string parentPath, int width, int height, string field, out ValidationProblem problem)
        {
            problem = null;
            if (string.IsNullOrWhiteSpace(parentPath)) return new List<SceneCamera>(); // Core reports the empty path
            var parent = SceneObjects.Find(parentPath);
            if (parent == null)
            {
                problem = new ValidationProblem(field + ".parent", parentPath, "names no object in the open scenes.",
                    "Give the hierarchy path of the parent of your cameras (e.g. \"Set/Shots\"), with its scene open.");
                return null;
            }
            var cameras = new List<SceneCamera>();
            foreach (var camera in parent.GetComponentsInChildren<Camera>(false))
            {
                var read = Read(camera, width, height, field + ".parent", out problem);
                if (problem != null) return null;
                cameras.Add(read);
            }
            return cameras;
        }

        /// <summary>One camera's pose and its field of view at W × H, or a problem when the capture cannot reproduce it.</summary>
        public static SceneCamera Read(Camera camera, int width, int height, string field, out ValidationProblem problem)
        {
            var name = SceneObjectPath.Of(camera.gameObject);
            problem = null;
            if (camera.orthographic)
            {
                problem = new ValidationProblem(field, name, "is an orthographic camera; the datasets hold pinhole (perspective) cameras.",
                    "Switch it to Perspective, or move it out from under the parent.");
                return null;
            }
            problem = TemplateFraming.Problem(camera, width, height, name);
            if (problem != null) return null;
            var fov = width > 0 && height > 0 ? TemplateFraming.VerticalFieldOfView(camera, width, height) : camera.fieldOfView;
            // The capture camera takes position and rotation only: a Camera's view matrix ignores its Transform's scale.
            var t = camera.transform;
            var pose = new UnityPose(new Vector3d(t.position.x, t.position.y, t.position.z),
                new Quaterniond(t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w));
            return new SceneCamera(name, pose, fov);
        }
    }
}
