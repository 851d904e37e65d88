using System.Collections.Generic;
using System.Globalization;
using System.Text;
using UnityEditor;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Reads a volume source's box and the scene's obstacles for Core's <see cref="VolumeSampling"/>. The user's
    /// objects are only read.
    /// <para>
    /// The box is the object's Transform: its unit cube at <c>position</c>, <c>rotation</c> and <c>lossyScale</c>
    /// (what a scaled empty or a scaled Cube primitive shows in the Scene view).
    /// </para>
    /// <para>
    /// Obstacles are colliders, not renderer bounds: a collider is what the scene's author declared solid, a
    /// BoxCollider (the usual wall, floor or crate) is an exact oriented box, while a renderer's <c>bounds</c> is a
    /// world axis-aligned box that for a turned wall or a room's single mesh encloses open space, and a ground plane,
    /// sky dome or decal would reject everything. Read per enabled, non-trigger collider on an active object in the
    /// loaded scenes (the box object's own colliders excluded):
    /// BoxCollider → its <c>center</c> and <c>size</c> through its Transform (UnityCsReference 2022.3
    /// Modules/Physics/ScriptBindings/Dynamics.bindings.cs:416-419); SphereCollider, CapsuleCollider and convex
    /// MeshCollider → <c>Collider.bounds</c>, the world-space AABB (Dynamics.bindings.cs:328), after
    /// <c>Physics.SyncTransforms()</c> (line 1575) so moved objects' bounds are current in edit mode; a non-convex
    /// MeshCollider, a TerrainCollider and other kinds are not obstacles — their AABB would hold the room or the
    /// landscape the cameras are meant to be in.
    /// </para>
    /// </summary>
    public static class VolumeSource
    {
        /// <summary>
        /// The box and obstacles, and for a path the world positions of <paramref name="waypointsPath"/>'s direct
        /// children in hierarchy order (<c>Transform.childCount</c> / <c>GetChild(i)</c>, UnityCsReference 2022.3
        /// Runtime/Transform/ScriptBindings/Transform.bindings.cs:397, 498; inactive children count too: they are
        /// markers, not content); null with a problem when an object is not in the open scenes.
        /// </summary>
        public static VolumeScene Read(string boxPath, string field, out ValidationProblem problem, string waypointsPath = null)
        {
            problem = null;
            if (string.IsNullOrWhiteSpace(boxPath)) return null; // Core reports the empty path
            var boxObject = SceneObjects.Find(boxPath);
            if (boxObject == null)
            {
                problem = new ValidationProblem(field + ".box", boxPath, "names no object in the open scenes.",
                    "Give the hierarchy path of the object whose Transform is the capture box (e.g. \"CaptureVolume\"), with its scene open.");
                return null;
            }
            var t = boxObject.transform;
            var box = new OrientedBox(SceneObjectPath.Of(boxObject), ToCore(t.position), ToCore(t.rotation), Abs(ToCore(t.lossyScale)));
            List<Vector3d> waypoints = null;
            if (!string.IsNullOrWhiteSpace(waypointsPath))
            {
                var pathObject = SceneObjects.Find(waypointsPath);
                if (pathObject == null)
                {
                    problem = new ValidationProblem(field + ".waypoints", waypointsPath, "names no object in the open scenes.",
                        "Give the hierarchy path of the object whose children are the waypoints (e.g. \"Flythrough\"), with its scene open.");
                    return null;
                }
                var parent = pathObject.transform;
                waypoints = new List<Vector3d>(parent.childCount);
                for (var i = 0; i < parent.childCount; i++) waypoints.Add(ToCore(parent.GetChild(i).position));
            }
            return new VolumeScene(box, Obstacles(boxObject), waypoints);
        }

        // The Scene-view preview resolves the sources ten times a second; reading every collider of a large environment
        // each time would make the editor stutter. Cached per excluded object and set of loaded scenes, and forgotten on
        // any change the editor publishes (ObjectChangeEvents.changesPublished: moved, added, removed, edited objects),
        // as AnimatedCameraSampler does; DatasetCapture.Prepare clears it, so a capture always reads the scene afresh.
        static readonly Dictionary<string, List<OrientedBox>> ObstacleCache = new Dictionary<string, List<OrientedBox>>();
        static bool _listening;

        /// <summary>Forgets the cached obstacles (a capture about to start, tests, or a change the events do not report).</summary>
        public static void ClearCache() => ObstacleCache.Clear();

        /// <summary>The obstacle boxes of the loaded scenes, in hierarchy order, leaving out <paramref name="exclude"/> and its children.</summary>
        public static List<OrientedBox> Obstacles(GameObject exclude)
        {
            if (!_listening)
            {
                _listening = true;
                ObjectChangeEvents.changesPublished += (ref ObjectChangeEventStream stream) => ObstacleCache.Clear();
            }
            var key = CacheKey(exclude);
            if (!ObstacleCache.TryGetValue(key, out var obstacles))
                ObstacleCache[key] = obstacles = ReadObstacles(exclude);
            return new List<OrientedBox>(obstacles);
        }

        static string CacheKey(GameObject exclude)
        {
            var key = new StringBuilder(exclude == null ? "-" : exclude.GetInstanceID().ToString(CultureInfo.InvariantCulture));
            for (var s = 0; s < SceneManager.sceneCount; s++)
            {
                var scene = SceneManager.GetSceneAt(s);
                key.Append('|').Append(scene.handle.ToString(CultureInfo.InvariantCulture)).Append(scene.isLoaded ? 'L' : 'u');
            }
            return key.ToString();
        }

        static List<OrientedBox> ReadObstacles(GameObject exclude)
        {
            Physics.SyncTransforms();
            var obstacles = new List<OrientedBox>();
            for (var s = 0; s < SceneManager.sceneCount; s++)
            {
                var scene = SceneManager.GetSceneAt(s);
                if (!scene.isLoaded) continue;
                foreach (var root in scene.GetRootGameObjects())
                foreach (var collider in root.GetComponentsInChildren<Collider>(false))
                {
                    if (!collider.enabled || collider.isTrigger) continue;
                    if (exclude != null && collider.transform.IsChildOf(exclude.transform)) continue;
                    var box = ToBox(collider);
                    if (box != null) obstacles.Add(box);
                }
            }
            return obstacles;
        }

        static OrientedBox ToBox(Collider collider)
        {
            var name = SceneObjectPath.Of(collider.gameObject);
            var t = collider.transform;
            if (collider is BoxCollider box)
                return new OrientedBox(name, ToCore(t.TransformPoint(box.center)), ToCore(t.rotation), Abs(ToCore(Vector3.Scale(box.size, t.lossyScale))));
            var solid = collider is SphereCollider || collider is CapsuleCollider || collider is MeshCollider mesh && mesh.convex;
            if (!solid) return null;
            var bounds = collider.bounds;
            return OrientedBox.AxisAligned(name, ToCore(bounds.center), ToCore(bounds.size));
        }

        static Vector3d ToCore(Vector3 v) => new Vector3d(v.x, v.y, v.z);
        static Quaterniond ToCore(Quaternion q) => new Quaterniond(q.x, q.y, q.z, q.w);
        static Vector3d Abs(Vector3d v) => new Vector3d(System.Math.Abs(v.X), System.Math.Abs(v.Y), System.Math.Abs(v.Z));
    }
}
