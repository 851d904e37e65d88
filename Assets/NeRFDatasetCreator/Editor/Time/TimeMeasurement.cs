using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// What a dynamic capture needs to know about its target before planning: the clip length (for
    /// <c>time.end: "clip"</c>), the bounds over the whole time range (they decide the automatic distance, the
    /// normalisation and aabb_scale), the surface at the first step (points3d.ply), and what will not follow time (physics, scripts). Bounds are measured on a
    /// temporary copy in a preview scene, posed by <see cref="ContentClock"/>; the user's objects are only read.
    /// </summary>
    static class TimeMeasurement
    {
        /// <summary>Times sampled for the bounds: every step up to this many, else this many spread over the range.</summary>
        public const int MaxBoundsSamples = 16;

        public static PlanTarget Measure(GameObject target, DatasetSettings settings, PlanTarget still, List<ValidationProblem> warnings)
        {
            var time = settings.Time;
            if (target == null || time == null || !time.Enabled) return still;
            Warn(target, warnings);
            var clip = ContentClock.ClipLength(target, time.Sources);
            TimeRange range;
            try
            {
                range = TimePlanning.Resolve(settings, clip);
            }
            catch (InvalidParameterException)
            {
                return new PlanTarget(still.Centre, still.BoundingRadius, clip); // CapturePlan.Check reports it
            }
            if (range == null) return new PlanTarget(still.Centre, still.BoundingRadius, clip);
            var bounds = BoundsOverRange(target, range, settings.Seed);
            if (!bounds.HasValue) return new PlanTarget(still.Centre, still.BoundingRadius, clip);
            var b = bounds.Value;
            return new PlanTarget(new Vector3d(b.center.x, b.center.y, b.center.z), b.extents.magnitude, clip);
        }

        static void Warn(GameObject target, List<ValidationProblem> warnings)
        {
            var scripts = 0;
            foreach (var behaviour in target.GetComponentsInChildren<MonoBehaviour>(true))
                if (behaviour != null && behaviour.enabled) scripts++;
            if (scripts > 0)
                warnings.Add(new ValidationProblem("time.sources", scripts + " enabled script" + (scripts == 1 ? "" : "s"),
                    "on the target will not run during the capture: motion made in Update or by coroutines is not captured, only Timeline, Animator, Animation and particle time.",
                    "Drive the motion with an Animator, a Timeline or an animation clip (record it with the Animation window if needed)."));
            // By type name: Rigidbody lives in the physics module, which this package does not require.
            var bodies = 0;
            foreach (var component in target.GetComponentsInChildren<Component>(true))
            {
                var name = component == null ? null : component.GetType().FullName;
                if (name == "UnityEngine.Rigidbody" || name == "UnityEngine.Rigidbody2D") bodies++;
            }
            if (bodies > 0)
                warnings.Add(new ValidationProblem("time.sources", bodies + " Rigidbod" + (bodies == 1 ? "y" : "ies"),
                    "on the target: physics is not simulated during the capture, so bodies stay where they are at every time step.",
                    "Bake the simulation into an animation clip (e.g. with the Recorder's Animation Clip recorder) and capture that."));
        }

        static Bounds? BoundsOverRange(GameObject target, TimeRange range, long seed) => WithCopy(target, copy =>
        {
            var clock = new ContentClock(range.Sources, seed);
            var samples = Math.Min(range.Steps, MaxBoundsSamples);
            Bounds? all = null;
            for (var i = 0; i < samples; i++)
            {
                clock.Show(copy, range.SecondsAt(i / (double)(samples - 1)));
                var posed = PosedBounds(copy);
                if (posed.HasValue) all = Union(all, posed.Value);
            }
            return all;
        });

        /// <summary>
        /// The target's surface for points3d.ply at the first time step (what Dynamic 3D Gaussians' init_pt_cld.npz and
        /// 3DGS start from), read from a copy posed by <see cref="ContentClock"/>; null for a static capture (the target
        /// as it stands is read instead).
        /// </summary>
        public static List<SurfaceMesh> SurfaceAtStart(GameObject target, TimeRange range, long seed, List<ValidationProblem> warnings)
        {
            if (target == null || range == null) return null;
            return WithCopy(target, copy =>
            {
                new ContentClock(range.Sources, seed).Show(copy, range.StartSeconds);
                return TargetSurface.Collect(copy, warnings);
            });
        }

        /// <summary>Runs <paramref name="use"/> on a temporary copy of the target in a preview scene, scripts off, then destroys it.</summary>
        static T WithCopy<T>(GameObject target, Func<GameObject, T> use)
        {
            using (var copy = SceneCopy.OfObject(target, "time copy")) return use(copy.Root);
        }

        /// <summary>
        /// TargetMeshes.WorldBounds, but skinned meshes measured in their current pose rather than their bind pose:
        /// <c>BakeMesh(mesh, useScale: true)</c> compensates the renderer's position, rotation and scale ("If true, the
        /// baked Mesh is the same size as the original", Scripting API SkinnedMeshRenderer.BakeMesh 2023.2+), so its
        /// vertices are in the renderer's local space and the full <c>localToWorldMatrix</c> takes them to the world,
        /// as <see cref="TargetSurface.Collect"/> does (SkinnedTargetSurfaceTests). Dropping the scale would measure a
        /// character under a 0.01 (centimetre FBX) parent 100 times too large.
        /// </summary>
        static Bounds? PosedBounds(GameObject root)
        {
            Bounds? all = null;
            var baked = new Mesh { hideFlags = HideFlags.HideAndDontSave };
            try
            {
                foreach (var pair in TargetMeshes.Of(root))
                {
                    if (!(pair.Key is SkinnedMeshRenderer skinned)) continue;
                    skinned.BakeMesh(baked, true);
                    var toWorld = skinned.transform.localToWorldMatrix;
                    foreach (var v in baked.vertices) all = Union(all, new Bounds(toWorld.MultiplyPoint3x4(v), Vector3.zero));
                }
            }
            finally
            {
                Object.DestroyImmediate(baked);
            }
            var rigid = TargetMeshes.WorldBounds(root, includeSkinned: false);
            return rigid.HasValue ? Union(all, rigid.Value) : all;
        }

        static Bounds? Union(Bounds? a, Bounds b)
        {
            if (!a.HasValue) return b;
            var grown = a.Value;
            grown.Encapsulate(b);
            return grown;
        }
    }
}
