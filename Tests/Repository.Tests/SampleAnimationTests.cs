using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using YamlDotNet.RepresentationModel;

namespace NerfDatasetCreator.Repository.Tests
{
    /// <summary>
    /// The sample's animated target is hand-written YAML that no Unity Editor has imported here: these tests hold the
    /// scene, the legacy clip and its .meta to what a user of the dynamic sample configs relies on. Class IDs: 1
    /// GameObject, 4 Transform, 23 MeshRenderer, 33 MeshFilter, 74 AnimationClip, 111 Animation, 1660057539
    /// SceneRoots (Unity Manual, "YAML class ID reference").
    /// </summary>
    [TestFixture]
    public class SampleAnimationTests
    {
        static readonly string[] DynamicConfigs = { "nerf-sample-dynamic.json", "nerf-sample-multiview.json" };

        static UnityYaml Scene => UnityYaml.Load(SampleClip.ScenePath);

        static string ClipGuid => Regex.Match(File.ReadAllText(SampleClip.ClipPath + ".meta"), @"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline).Groups[1].Value;

        static DatasetSettings Config(string file) =>
            DatasetSettingsJson.ReadFile(RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", file)).Settings;

        [Test]
        public void EveryFileIdOfTheSceneIsUniqueAndEveryReferenceWithinItResolves()
        {
            var scene = Scene;
            var ids = scene.Objects.Select(o => o.FileId).ToList();
            Assert.That(ids, Is.Unique);
            var local = new List<string>();
            foreach (var o in scene.Objects) CollectLocalReferences(o.Body, local);
            Assert.That(local.Where(id => id != "0").Except(ids), Is.Empty, "fileIDs referenced in the scene without a guid name objects of the scene");
        }

        static void CollectLocalReferences(YamlNode node, List<string> into)
        {
            if (node is YamlMappingNode map)
            {
                var keys = map.Children.Keys.OfType<YamlScalarNode>().Select(k => k.Value).ToList();
                if (keys.Contains("fileID") && !keys.Contains("guid")) into.Add(UnityYaml.Reference(map).FileId);
                foreach (var child in map.Children.Values) CollectLocalReferences(child, into);
            }
            else if (node is YamlSequenceNode list)
                foreach (var child in list.Children) CollectLocalReferences(child, into);
        }

        [TestCaseSource(nameof(DynamicConfigs))]
        public void TheConfigNamesTheAnimatedTargetAndTheLegacyAnimationSource(string file)
        {
            var settings = Config(file);
            Assert.That(settings.Target, Is.EqualTo(SampleClip.AnimatedTarget));
            Assert.That(settings.Scene, Is.EqualTo("NeRFSample.unity"), "beside the config, so it works where Package Manager imports the sample");
            Assert.That(ScenePath.Resolve(settings.Scene, RepositoryPaths.Combine("Assets", "Samples", "NeRFSample", file), RepositoryPaths.Root),
                Is.EqualTo("Assets/Samples/NeRFSample/NeRFSample.unity"));
            Assert.That(settings.Time.Sources & TimeSources.Animation, Is.EqualTo(TimeSources.Animation), "the clip is a legacy Animation's");
            Assert.That(settings.Time.Enabled, Is.True);
        }

        [Test]
        public void TheAnimatedTargetIsASceneRootAwayFromTheStaticTargetWithTheCubeAsItsOnlyChild()
        {
            var scene = Scene;
            var target = scene.GameObject(SampleClip.AnimatedTarget);
            var transform = scene.Component(target, 4);
            Assert.That(UnityYaml.Reference(UnityYaml.Node(transform.Body, "m_Father")).FileId, Is.EqualTo("0"));
            var roots = UnityYaml.Sequence(scene.OfClass(1660057539).Single().Body, "m_Roots").Select(r => UnityYaml.Reference(r).FileId);
            Assert.That(roots, Does.Contain(transform.FileId));
            // Unrotated and unscaled, so the cube's world position is the root's plus its local position.
            Assert.That(UnityYaml.Text(UnityYaml.Map(transform.Body, "m_LocalRotation"), "w"), Is.EqualTo("1"));
            Assert.That(UnityYaml.Vector3(UnityYaml.Node(transform.Body, "m_LocalScale")), Is.EqualTo(new[] { 1.0, 1, 1 }));
            Assert.That(UnityYaml.Vector3(UnityYaml.Node(transform.Body, "m_LocalPosition")), Is.EqualTo(new[] { 3.0, 0, 0 }),
                "3 units along x: clear of NeRFTarget (radius about 1.1 about the origin), which stays as it was");

            var children = UnityYaml.Sequence(transform.Body, "m_Children").Select(c => scene.ById(UnityYaml.Reference(c).FileId)).ToList();
            Assert.That(children, Has.Count.EqualTo(1));
            var cube = scene.ById(UnityYaml.Reference(UnityYaml.Node(children[0].Body, "m_GameObject")).FileId);
            Assert.That(UnityYaml.Text(cube.Body, "m_Name"), Is.EqualTo(SampleClip.CubeName));
            Assert.That(UnityYaml.Reference(UnityYaml.Node(children[0].Body, "m_Father")).FileId, Is.EqualTo(transform.FileId));
        }

        [Test]
        public void TheCubeIsTheBuiltInCubeMeshWithTheDefaultMaterial_AsTheStaticTargetsParts()
        {
            var scene = Scene;
            var cube = scene.GameObject(SampleClip.CubeName);
            // The static target's Base and Pointer use the same built-in references (fileID 10202 in the built-in
            // extra resources, guid 0000000000000000e000000000000000; Default-Material 10303 in …f000…).
            var staticMesh = UnityYaml.Reference(UnityYaml.Node(scene.Component(scene.GameObject("Base"), 33).Body, "m_Mesh"));
            var staticMaterial = UnityYaml.Reference(UnityYaml.Sequence(scene.Component(scene.GameObject("Base"), 23).Body, "m_Materials")[0]);
            var mesh = UnityYaml.Reference(UnityYaml.Node(scene.Component(cube, 33).Body, "m_Mesh"));
            var material = UnityYaml.Reference(UnityYaml.Sequence(scene.Component(cube, 23).Body, "m_Materials").Single());
            Assert.That(mesh, Is.EqualTo(staticMesh));
            Assert.That(mesh.FileId, Is.EqualTo("10202"));
            Assert.That(material, Is.EqualTo(staticMaterial));
            Assert.That(UnityYaml.Text(scene.Component(cube, 23).Body, "m_Enabled"), Is.EqualTo("1"));
        }

        [Test]
        public void TheAnimationComponentPlaysTheClipThatTheMetaNames()
        {
            var scene = Scene;
            var animation = scene.Component(scene.GameObject(SampleClip.AnimatedTarget), 111);
            Assert.That(animation.ClassName, Is.EqualTo("Animation"));
            Assert.That(UnityYaml.Text(animation.Body, "m_Enabled"), Is.EqualTo("1"));
            // A reference to an asset's main object: its fileID is the .meta's mainObjectFileID, type 2 (an asset of the project).
            var meta = File.ReadAllText(SampleClip.ClipPath + ".meta");
            Assert.That(meta, Does.Contain("\nNativeFormatImporter:\n"));
            Assert.That(meta, Does.Contain("\n  mainObjectFileID: 7400000\n"));
            var expected = new UnityYaml.ObjectReference("7400000", ClipGuid, "2");
            Assert.That(ClipGuid, Has.Length.EqualTo(32));
            Assert.That(UnityYaml.Reference(UnityYaml.Node(animation.Body, "m_Animation")), Is.EqualTo(expected), "the default clip (Animation.clip, what ContentClock samples)");
            Assert.That(UnityYaml.Sequence(animation.Body, "m_Animations").Select(UnityYaml.Reference), Is.EqualTo(new[] { expected }));

            var clip = SampleClip.Load().File.Objects.Single();
            Assert.That((clip.ClassId, clip.FileId, clip.ClassName), Is.EqualTo((74, "7400000", "AnimationClip")));
        }

        [Test]
        public void TheClipIsLegacyAndMovesOnlyTheCubeByItsPathFromTheAnimationsObject()
        {
            var clip = SampleClip.Load().Clip;
            // A legacy Animation component plays only legacy clips (Manual: "Animation" component, legacy).
            Assert.That(UnityYaml.Text(clip, "m_Legacy"), Is.EqualTo("1"));
            foreach (var section in new[] { "m_EulerCurves", "m_PositionCurves", "m_EditorCurves" })
                Assert.That(UnityYaml.Sequence(clip, section).Select(c => UnityYaml.Text((YamlMappingNode)c, "path")), Is.All.EqualTo(SampleClip.CubeName), section);
            foreach (var section in new[] { "m_RotationCurves", "m_CompressedRotationCurves", "m_ScaleCurves", "m_FloatCurves", "m_PPtrCurves", "m_Events" })
                Assert.That(UnityYaml.Sequence(clip, section), Is.Empty, section);
            var editor = UnityYaml.Sequence(clip, "m_EditorCurves").Select(c => UnityYaml.Text((YamlMappingNode)c, "attribute"));
            Assert.That(editor, Is.EquivalentTo(new[]
            {
                "m_LocalPosition.x", "m_LocalPosition.y", "m_LocalPosition.z",
                "localEulerAnglesRaw.x", "localEulerAnglesRaw.y", "localEulerAnglesRaw.z",
            }));
            foreach (var curve in UnityYaml.Sequence(clip, "m_EulerCurves").Concat(UnityYaml.Sequence(clip, "m_PositionCurves")).Concat(UnityYaml.Sequence(clip, "m_EditorCurves")))
            {
                var body = UnityYaml.Map((YamlMappingNode)curve, "curve");
                Assert.That(UnityYaml.Text(body, "m_PreInfinity") + UnityYaml.Text(body, "m_PostInfinity"), Is.EqualTo("22"), "clamped outside the keys");
                Assert.That(UnityYaml.Text(body, "m_RotationOrder"), Is.EqualTo("4"), "Unity's Z-X-Y Euler order");
            }
        }

        [Test]
        public void TheKeyframesAreTheIntendedOnes()
        {
            var clip = SampleClip.Load();
            var position = clip.VectorCurve("m_PositionCurves", SampleClip.CubeName);
            var euler = clip.VectorCurve("m_EulerCurves", SampleClip.CubeName);
            Assert.That(position[0].Select(k => k.Time), Is.EqualTo(new[] { 0.0, 1, 2 }));
            Assert.That(position.Select(axis => axis.Select(k => k.Value)), Is.EqualTo(new[]
            {
                new[] { -0.6, 0, 0.6 }, new[] { 0.4, 0.8, 0.4 }, new[] { 0.0, 0, 0 },
            }));
            Assert.That(euler[0].Select(k => k.Time), Is.EqualTo(new[] { 0.0, 2 }));
            Assert.That(euler.Select(axis => axis.Select(k => k.Value)), Is.EqualTo(new[] { new[] { 0.0, 0 }, new[] { 0.0, 90 }, new[] { 0.0, 0 } }));
            Assert.That(clip.StartTime, Is.EqualTo(0));
            Assert.That(clip.StopTime, Is.EqualTo(2), "the clip's length (AnimationClip.length), which time.end \"clip\" resolves to");
        }

        [Test]
        public void EveryKeyIsLinear_ItsSlopesAreTheSecantsOfItsSegments()
        {
            // Linear tangents (what "Both Tangents ▸ Linear" sets): a key's in-slope is the secant of the segment
            // before it, its out-slope that of the segment after it (0 where there is none); the Hermite spline between
            // such keys is the straight line, so the pose between keys is the linear interpolation.
            var clip = SampleClip.Load();
            foreach (var curve in new[] { clip.VectorCurve("m_PositionCurves", SampleClip.CubeName), clip.VectorCurve("m_EulerCurves", SampleClip.CubeName) })
                foreach (var keys in curve)
                    for (var i = 0; i < keys.Count; i++)
                    {
                        var before = i > 0 ? (keys[i].Value - keys[i - 1].Value) / (keys[i].Time - keys[i - 1].Time) : 0;
                        var after = i + 1 < keys.Count ? (keys[i + 1].Value - keys[i].Value) / (keys[i + 1].Time - keys[i].Time) : 0;
                        Assert.That(keys[i].InSlope, Is.EqualTo(before).Within(1e-9), keys[i].ToString());
                        Assert.That(keys[i].OutSlope, Is.EqualTo(after).Within(1e-9), keys[i].ToString());
                    }
        }

        [Test]
        public void TheEditorCurvesAreTheRuntimeCurvesComponentByComponent()
        {
            // Unity keeps a clip twice: runtime curves (m_PositionCurves, m_EulerCurves) and one float curve per
            // component for the Animation window (m_EditorCurves). They must agree, whichever one Unity reads.
            // tangentMode 69 = broken (1) | Linear (2) << 1 | Linear << 5, the encoding behind AnimationUtility.TangentMode.
            var clip = SampleClip.Load();
            var pairs = new[] { ("m_PositionCurves", "m_LocalPosition"), ("m_EulerCurves", "localEulerAnglesRaw") };
            foreach (var (runtime, attribute) in pairs)
            {
                var curve = clip.VectorCurve(runtime, SampleClip.CubeName);
                for (var axis = 0; axis < 3; axis++)
                {
                    var editor = clip.EditorCurve(attribute + "." + "xyz"[axis], SampleClip.CubeName);
                    Assert.That(editor.Select(e => e.Key), Is.EqualTo(curve[axis]), attribute + "." + "xyz"[axis]);
                    Assert.That(editor.Select(e => e.TangentMode), Is.All.EqualTo(69));
                }
            }
        }

        [TestCase(0.0)]
        [TestCase(0.5)]
        [TestCase(1.0)]
        [TestCase(1.5)]
        [TestCase(2.0)]
        [TestCase(0.25)]
        [TestCase(1.75)]
        public void ThePoseAtAKnownTimeIsTheHandDerivedOne(double seconds)
        {
            var (position, euler) = SampleClip.Load().Pose(seconds);
            var (expectedPosition, expectedEuler) = SampleClip.IntendedPose(seconds);
            Assert.That(position, Is.EqualTo(expectedPosition).Within(1e-12));
            Assert.That(euler, Is.EqualTo(expectedEuler).Within(1e-12));
        }

        [Test]
        public void TheHandDerivedPoseAtTheStartHalfwayAndTheEnd()
        {
            // Written out, independent of the clip: a wrong constant in IntendedPose would fail here.
            Assert.That(SampleClip.IntendedPose(0).Position, Is.EqualTo(new[] { -0.6, 0.4, 0 }));
            Assert.That(SampleClip.IntendedPose(1).Position, Is.EqualTo(new[] { 0.0, 0.8, 0 }).Within(1e-12));
            Assert.That(SampleClip.IntendedPose(2).Position, Is.EqualTo(new[] { 0.6, 0.4, 0 }).Within(1e-12));
            Assert.That(SampleClip.IntendedPose(1).Euler, Is.EqualTo(new[] { 0.0, 45, 0 }));
            Assert.That(SampleClip.IntendedPose(2).Euler, Is.EqualTo(new[] { 0.0, 90, 0 }));
        }

        [Test]
        public void TheSceneHoldsTheCubeInTheClipsFirstPose()
        {
            // The scene at rest looks like time 0, so the Scene view shows where the capture starts.
            var scene = Scene;
            var transform = scene.Component(scene.GameObject(SampleClip.CubeName), 4);
            var (position, euler) = SampleClip.Load().Pose(0);
            Assert.That(UnityYaml.Vector3(UnityYaml.Node(transform.Body, "m_LocalPosition")), Is.EqualTo(position));
            Assert.That(UnityYaml.Vector3(UnityYaml.Node(transform.Body, "m_LocalEulerAnglesHint")), Is.EqualTo(euler));
            Assert.That(UnityYaml.Text(UnityYaml.Map(transform.Body, "m_LocalRotation"), "w"), Is.EqualTo("1"));
            Assert.That(UnityYaml.Vector3(UnityYaml.Node(transform.Body, "m_LocalScale")), Is.EqualTo(new[] { 0.3, 0.3, 0.8 }), "long along z, so its turn shows");
        }

        [TestCaseSource(nameof(DynamicConfigs))]
        public void TheClipCoversTheConfigsTimeRange(string file)
        {
            var settings = Config(file);
            var clip = SampleClip.Load();
            var range = TimePlanning.Resolve(settings, clip.StopTime);
            Assert.That(range.StartSeconds, Is.GreaterThanOrEqualTo(clip.StartTime));
            Assert.That(range.EndSeconds, Is.LessThanOrEqualTo(clip.StopTime));
            Assert.That(range.EndSeconds - range.StartSeconds, Is.EqualTo(2.0), "the whole clip: end \"clip\" from 0");
        }
    }
}
