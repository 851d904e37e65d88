using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using UnityEngine;
using UnityEngine.Playables;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// An animated camera whose CinemachineBrain is driven by a Cinemachine track on a Timeline (Cinemachine 2.x or 3.x,
    /// read by name through <see cref="CinemachineApi"/>). The brain, the virtual cameras, the director and the targets
    /// live on different root objects, so the camera's whole scene is copied into a preview scene with the references
    /// between roots pointing at the copies (<see cref="SceneCopy"/>); Cinemachine's components stay enabled there,
    /// every other script is disabled. At each sample time the copy is posed by <see cref="ContentClock"/> — the
    /// directors driving the brain set to the time and evaluated, so the Cinemachine mixer hands the brain its shot or
    /// blend (<c>SetCameraOverride</c>), Animators and legacy clips stepped as for any animated camera — and then the
    /// copied brain's <c>ManualUpdate()</c> updates the virtual cameras and writes the result to its Camera's transform
    /// and lens. The pose and field of view are read from that Camera, as for any scene camera.
    /// <para>
    /// Deterministic by construction: in edit mode the brain takes the Timeline's delta time, and the mixer gives -1
    /// while scrubbing, so every virtual camera is placed from scratch, without damping, noise or the previous frame
    /// (<see cref="CinemachineApi.Scrubbing"/> makes sure no cache or preview playback changes that). The poses are those
    /// the Timeline window shows when scrubbed to each time. Refused: a soloed virtual camera, a Timeline without a
    /// Cinemachine track bound to the brain, a sample where no shot is active (<see cref="CinemachineShots"/>), and a
    /// live virtual camera outside the copied scene. Damping is reported as a warning: play mode's damped result depends
    /// on real frame times.
    /// </para>
    /// </summary>
    static class CinemachineCameraSampler
    {
        public sealed class Result
        {
            public List<SceneCamera> Cameras;
            public List<ValidationProblem> Warnings = new List<ValidationProblem>();
        }

        /// <summary>What the copy's clock evaluates: the Cinemachine rig's directors, Animators and legacy clips.</summary>
        const TimeSources Drivers = TimeSources.Timeline | TimeSources.Animator | TimeSources.Animation;

        public static Result Sample(Camera camera, Component brain, CameraSourceSettings source, int width, int height, string field,
            out ValidationProblem problem)
        {
            problem = null;
            var name = SceneObjectPath.Of(camera.gameObject);
            var api = CinemachineApi.Of(brain);
            if (api.SoloCamera is Component solo && solo != null)
            {
                problem = new ValidationProblem(field + ".camera", name,
                    "is driven by Cinemachine " + api.Version + ", and the virtual camera \"" + solo.name + "\" is soloed: every brain shows it instead of the Timeline's shots.",
                    "Turn Solo off on that virtual camera's inspector, then plan again.");
                return null;
            }
            if (!camera.gameObject.scene.IsValid() || !camera.gameObject.scene.isLoaded)
            {
                problem = new ValidationProblem(field + ".camera", name, "is not in a loaded scene.", "Open the camera's scene.");
                return null;
            }

            using (var copy = SceneCopy.Of(camera.gameObject.scene, script => IsCinemachine(script.GetType())))
            using (api.Scrubbing())
            {
                var copiedCamera = copy.CopyOf(camera);
                var copiedBrain = copy.CopyOf(brain);
                if (copiedCamera == null || copiedBrain == null) throw new InvalidOperationException("The copy of " + name + " was not found.");

                // The directors whose Cinemachine track is bound to this brain drive it; other directors are left out
                // (their Timelines are not this camera's), so the clock sees only these.
                var tracks = new List<KeyValuePair<string, List<ShotSpan>>>();
                double length = 0, rate = 0;
                foreach (var director in copy.Holder.GetComponentsInChildren<PlayableDirector>(true))
                {
                    var driving = CinemachineApi.TracksDriving(director, copiedBrain);
                    if (driving.Count == 0)
                    {
                        director.playableAsset = null;
                        continue;
                    }
                    tracks.AddRange(driving);
                    length = Math.Max(length, director.playableAsset.duration);
                    if (rate <= 0) rate = AnimatedCameraSampler.TimelineFrameRate(director);
                    director.RebuildGraph(); // the graph resolves the shots' ExposedReferences when built: after the remap (PlayableDirector.bindings.cs:93)
                }
                if (tracks.Count == 0)
                {
                    problem = new ValidationProblem(field + ".camera", name,
                        "has a CinemachineBrain (Cinemachine " + api.Version + "), but no PlayableDirector in its scene has a Cinemachine track bound to it.",
                        "Bind the Timeline's Cinemachine track to this camera's brain (Timeline window, the track's binding field), or pick the camera the track drives.");
                    return null;
                }
                var shots = tracks.SelectMany(t => t.Value).ToList();
                var trackNames = string.Join(", ", tracks.Select(t => t.Key));

                double[] times;
                try
                {
                    var frameRate = source.FrameRate > 0 ? source.FrameRate : rate > 0 ? rate : AnimatedCameraSampling.DefaultFrameRate;
                    times = AnimatedCameraSampling.Times(source.Start, AnimatedCameraSampling.ResolveEnd(source.End, length), source.Samples, source.FrameStep, frameRate, field);
                }
                catch (InvalidParameterException e)
                {
                    problem = e.Problems[0];
                    return null;
                }
                var evaluated = CinemachineShots.EvaluationTimes(shots, times, field, trackNames, out problem);
                if (evaluated == null) return null;

                var clock = new ContentClock(Drivers, 0);
                var result = new Result { Cameras = new List<SceneCamera>(times.Length) };
                var damped = new List<Component>();
                for (var i = 0; i < times.Length; i++)
                {
                    clock.Show(copy.Holder, evaluated[i]);
                    // Twice: in 3.x the brain refreshes the cameras that were live before it takes the Timeline's new
                    // blend (releases/3.1.1 CinemachineBrain.cs:603 before 544–546); the second pass updates the ones live
                    // now. With delta time -1 an update depends on this time alone (CinemachineCore.cs:353 in 2.10.3,
                    // CameraUpdateManager.cs:189 in 3.1.1 skip a repeat only for delta time ≥ 0), so a repeat changes nothing else.
                    api.ManualUpdate(copiedBrain);
                    api.ManualUpdate(copiedBrain);
                    var time = times[i].ToString("0.####", CultureInfo.InvariantCulture);
                    foreach (var live in api.LiveCameras(copiedBrain))
                    {
                        if (live.gameObject.scene != copy.Preview)
                        {
                            problem = new ValidationProblem(field + ".camera", name + " @ " + time + " s",
                                "shows the virtual camera \"" + SceneObjectPath.Of(live.gameObject) + "\" from another scene (by its priority), not one of the Timeline's shots.",
                                "Keep the Timeline's virtual cameras in the camera's scene, and sample only while a shot is active.");
                            return null;
                        }
                        if (!damped.Contains(live) && CinemachineApi.MaxDampTime(live) > 0 &&
                            (CinemachineApi.Follow(live) != null || CinemachineApi.LookAt(live) != null))
                            damped.Add(live);
                    }
                    var read = SceneCameraSources.Read(copiedCamera, width, height, field + ".camera", out problem);
                    if (problem != null) return null;
                    result.Cameras.Add(new SceneCamera(name + " @ " + time + " s", read.Pose, read.VerticalFovDegrees));
                }
                foreach (var vcam in damped)
                {
                    var original = copy.OriginalOf(vcam);
                    result.Warnings.Add(new ValidationProblem(field + ".camera",
                        original != null ? SceneObjectPath.Of(original.gameObject) : vcam.name,
                        "damps its Follow / LookAt tracking (up to " + CinemachineApi.MaxDampTime(vcam).ToString("0.##", CultureInfo.InvariantCulture) +
                        " s); the camera is sampled as the Timeline window shows it when scrubbed, without damping — in play mode damping lags by an amount that depends on the frame times.",
                        "Nothing to do if the scrubbed poses are what you want (the images always match the written poses); set the damping to 0 to make play mode match them."));
                }
                return result;
            }
        }

        /// <summary>Cinemachine's own components (brain, virtual cameras, their pipeline and extensions); a user's subclass in another namespace is a user script.</summary>
        static bool IsCinemachine(Type type)
        {
            var ns = type.Namespace ?? "";
            return ns == "Cinemachine" || ns.StartsWith("Cinemachine.", StringComparison.Ordinal) ||
                   ns == "Unity.Cinemachine" || ns.StartsWith("Unity.Cinemachine.", StringComparison.Ordinal);
        }
    }
}
