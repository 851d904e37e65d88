using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.Playables;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A camera with a CinemachineBrain driven by a Timeline's Cinemachine track, built by reflection (the package
    /// references neither Cinemachine nor Timeline; the tests are ignored when they are not installed). Two virtual
    /// cameras on their own root objects: "CM Wide" 0–3 s, "CM Close" 2–5 s easing in linearly over 2–3 s, so the brain
    /// blends from Wide to Close with weight t − 2 there.
    /// </summary>
    public class CinemachineCameraTests
    {
        static readonly Vector3 WidePosition = new Vector3(0, 1, -10);
        static readonly Vector3 ClosePosition = new Vector3(4, 2, -6);
        static readonly Quaternion Turn = Quaternion.Euler(0, 30, 0);
        const float WideFov = 40, CloseFov = 60;

        static Type Find(params string[] fullNames)
        {
            foreach (var assembly in AppDomain.CurrentDomain.GetAssemblies())
                foreach (var name in fullNames)
                {
                    var type = assembly.GetType(name, false);
                    if (type != null) return type;
                }
            return null;
        }

        sealed class Rig
        {
            public Camera Camera;
            public Component Brain;
            public PlayableDirector Director;
            public List<Object> UserObjects = new List<Object>();
        }

        static Rig Build()
        {
            var brainType = Find("Unity.Cinemachine.CinemachineBrain", "Cinemachine.CinemachineBrain");
            var vcamType = Find("Unity.Cinemachine.CinemachineCamera", "Cinemachine.CinemachineVirtualCamera");
            var trackType = Find("Unity.Cinemachine.CinemachineTrack", "CinemachineTrack");
            var timelineType = Find("UnityEngine.Timeline.TimelineAsset");
            if (brainType == null || vcamType == null) Assert.Ignore("Cinemachine is not installed");
            if (trackType == null || timelineType == null) Assert.Ignore("Timeline (or Cinemachine's Timeline support) is not installed");

            var rig = new Rig();
            var cameraObject = new GameObject("Main Camera", typeof(Camera));
            rig.Camera = cameraObject.GetComponent<Camera>();
            rig.Camera.fieldOfView = 25; // not a shot's: only the brain may set it, on the copy
            rig.Brain = cameraObject.AddComponent(brainType);
            var wide = VirtualCamera(vcamType, "CM Wide", WidePosition, Quaternion.identity, WideFov);
            var close = VirtualCamera(vcamType, "CM Close", ClosePosition, Turn, CloseFov);

            var timeline = ScriptableObject.CreateInstance(timelineType);
            timeline.name = "Shots";
            // TimelineAsset.CreateTrack(Type, TrackAsset parent, string name).
            var track = (Object)timelineType.GetMethod("CreateTrack", new[] { typeof(Type), Find("UnityEngine.Timeline.TrackAsset"), typeof(string) })
                .Invoke(timeline, new object[] { trackType, null, "Cameras" });
            var directorObject = new GameObject("Timeline", typeof(PlayableDirector));
            rig.Director = directorObject.GetComponent<PlayableDirector>();
            rig.Director.playOnAwake = false;
            rig.Director.playableAsset = (PlayableAsset)timeline;
            rig.Director.SetGenericBinding(track, rig.Brain);
            Shot(track, rig.Director, wide, 0, 3, 0);
            Shot(track, rig.Director, close, 2, 3, 1);

            foreach (var root in rig.Camera.gameObject.scene.GetRootGameObjects())
                foreach (var t in root.GetComponentsInChildren<Transform>(true))
                {
                    rig.UserObjects.Add(t.gameObject);
                    rig.UserObjects.AddRange(t.GetComponents<Component>());
                }
            return rig;
        }

        static Component VirtualCamera(Type type, string name, Vector3 position, Quaternion rotation, float fov)
        {
            var go = new GameObject(name);
            go.transform.SetPositionAndRotation(position, rotation);
            var vcam = go.AddComponent(type);
            var lensField = type.GetField("Lens") ?? type.GetField("m_Lens"); // 3.x CinemachineCamera.Lens, 2.x m_Lens
            var lens = lensField.GetValue(vcam);
            lens.GetType().GetField("FieldOfView").SetValue(lens, fov);
            lensField.SetValue(vcam, lens);
            return vcam;
        }

        /// <summary>A Cinemachine shot of <paramref name="vcam"/> from start for duration, easing in linearly over <paramref name="easeIn"/>.</summary>
        static void Shot(Object track, PlayableDirector director, Component vcam, double start, double duration, double easeIn)
        {
            var clip = track.GetType().GetMethod("CreateDefaultClip", Type.EmptyTypes).Invoke(track, null);
            var clipType = clip.GetType();
            clipType.GetProperty("start").SetValue(clip, start);
            clipType.GetProperty("duration").SetValue(clip, duration);
            clipType.GetProperty("displayName").SetValue(clip, vcam.name);
            if (easeIn > 0)
            {
                clipType.GetProperty("easeInDuration").SetValue(clip, easeIn);
                var mode = clipType.GetProperty("blendInCurveMode");
                mode.SetValue(clip, Enum.Parse(mode.PropertyType, "Manual"));
                clipType.GetProperty("mixInCurve").SetValue(clip, AnimationCurve.Linear(0, 0, 1, 1));
            }
            // The shot names its camera by ExposedReference, resolved through the director's table.
            var shot = clipType.GetProperty("asset").GetValue(clip);
            var reference = shot.GetType().GetField("VirtualCamera");
            var exposed = reference.GetValue(shot);
            var id = new PropertyName(GUID.Generate().ToString());
            exposed.GetType().GetField("exposedName").SetValue(exposed, id);
            reference.SetValue(shot, exposed);
            director.SetReferenceValue(id, vcam);
        }

        static CameraSourceSettings Source(int samples) =>
            new CameraSourceSettings { Kind = CameraSourceKind.AnimatedCamera, ObjectPath = "Main Camera", Samples = samples };

        static Vector3 PositionOf(SceneCamera c) => new Vector3((float)c.Pose.Position.X, (float)c.Pose.Position.Y, (float)c.Pose.Position.Z);
        static Quaternion RotationOf(SceneCamera c) => new Quaternion((float)c.Pose.Rotation.X, (float)c.Pose.Rotation.Y, (float)c.Pose.Rotation.Z, (float)c.Pose.Rotation.W);

        [Test]
        public void ShotsGiveTheirVirtualCamerasPosesAndABlendMixesThem()
        {
            var scene = TestScene.Open();
            try
            {
                Build();
                AnimatedCameraSampler.ClearCache();
                // Every 0.5 s over the Timeline's 5 s.
                var sampled = AnimatedCameraSampler.Sample(Source(11), 64, 64, "splits.test.source", out var problem);
                Assert.That(problem, Is.Null, problem?.ToString());
                Assert.That(sampled, Has.Count.EqualTo(11));
                for (var i = 0; i < sampled.Count; i++)
                {
                    var t = i * 0.5;
                    // Before 2 s Wide alone, after 3 s Close alone (5 s: the last frame of the shot); between, Close's
                    // linear ease-in weight: positions and field of view lerp (CameraState.Lerp, LensSettings.Lerp), no
                    // LookAt, so the rotation slerps.
                    var w = (float)Math.Min(1, Math.Max(0, t - 2));
                    var expected = Vector3.Lerp(WidePosition, ClosePosition, w);
                    Assert.That(Vector3.Distance(PositionOf(sampled[i]), expected), Is.LessThan(1e-3f), "t = " + t);
                    Assert.That(Quaternion.Angle(RotationOf(sampled[i]), Quaternion.Slerp(Quaternion.identity, Turn, w)), Is.LessThan(0.1f), "t = " + t);
                    Assert.That(sampled[i].VerticalFovDegrees, Is.EqualTo(Mathf.Lerp(WideFov, CloseFov, w)).Within(1e-3), "t = " + t);
                }
                Assert.That(sampled[5].Name, Is.EqualTo("Main Camera @ 2.5 s"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void TheUsersCameraNeverMovesNoUserObjectChangesAndTwoRunsAreEqual()
        {
            var scene = TestScene.Open();
            try
            {
                var rig = Build();
                var dirty = rig.UserObjects.Select(EditorUtility.GetDirtyCount).ToList();
                var cameraPose = (rig.Camera.transform.position, rig.Camera.transform.rotation, rig.Camera.fieldOfView);
                AnimatedCameraSampler.ClearCache();
                var first = AnimatedCameraSampler.Sample(Source(9), 64, 64, "splits.test.source", out var problem);
                Assert.That(problem, Is.Null, problem?.ToString());
                AnimatedCameraSampler.ClearCache();
                var second = AnimatedCameraSampler.Sample(Source(9), 64, 64, "splits.test.source", out problem);
                Assert.That(problem, Is.Null);
                for (var i = 0; i < first.Count; i++)
                {
                    Assert.That(second[i].Pose.Position, Is.EqualTo(first[i].Pose.Position), "run 2, sample " + i);
                    Assert.That(second[i].Pose.Rotation, Is.EqualTo(first[i].Pose.Rotation), "run 2, sample " + i);
                    Assert.That(second[i].VerticalFovDegrees, Is.EqualTo(first[i].VerticalFovDegrees));
                }
                Assert.That((rig.Camera.transform.position, rig.Camera.transform.rotation, rig.Camera.fieldOfView), Is.EqualTo(cameraPose),
                    "the user's camera is where it was: only the copy's brain moved its copy");
                Assert.That(rig.UserObjects.Select(EditorUtility.GetDirtyCount).ToList(), Is.EqualTo(dirty), "no user object was changed");
                Assert.That(rig.Director.time, Is.EqualTo(0), "the user's director was not evaluated");
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void ASampleOutsideTheShotsIsRefused()
        {
            var scene = TestScene.Open();
            try
            {
                Build();
                AnimatedCameraSampler.ClearCache();
                var source = Source(3);
                source.End = 6; // past the last shot's end at 5 s
                Assert.That(AnimatedCameraSampler.Sample(source, 64, 64, "splits.test.source", out var problem), Is.Null);
                Assert.That(problem.Field, Is.EqualTo("splits.test.source.start"));
                Assert.That(problem.Value, Is.EqualTo("6 s"));
                Assert.That(problem.Reason, Does.Contain("CM Wide 0–3 s, CM Close 2–5 s"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }

        [Test]
        public void ABrainNoTrackDrivesIsRefused()
        {
            var scene = TestScene.Open();
            try
            {
                var rig = Build();
                Object.DestroyImmediate(rig.Director.gameObject);
                AnimatedCameraSampler.ClearCache();
                Assert.That(AnimatedCameraSampler.Sample(Source(3), 64, 64, "splits.test.source", out var problem), Is.Null);
                Assert.That(problem.Field, Is.EqualTo("splits.test.source.camera"));
                Assert.That(problem.Reason, Does.Contain("no PlayableDirector in its scene has a Cinemachine track bound to it"));
            }
            finally
            {
                TestScene.Close(scene);
            }
        }
    }
}
