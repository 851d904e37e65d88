using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Content changed on the copies between views (what a dynamic capture's ContentClock does through
    /// <see cref="CaptureOptions.BeforeView"/>): every pass of a view shows the content as posed for that view. One
    /// camera 3 units in front of the origin looking at it (+Z), 32×32, k = 1; the views are rendered in one blocking
    /// call, so all within one editor update.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class PosedContentCaptureTests : GpuSceneFixture
    {
        const int Size = 32;
        const double FovDegrees = 40.0;
        const double CameraDistance = 3.0;


        static List<RecordedView> Capture(GameObject target, int views, Action<GameObject, int> beforeView)
        {
            var options = new CaptureOptions
            {
                Width = Size, Height = Size, Supersampling = 1, VerticalFieldOfViewDegrees = FovDegrees, NearClip = 0.1, FarClip = 100,
                BeforeView = beforeView,
            };
            var pose = LookAt.FromPositions(new Vector3d(0, 0, -CameraDistance), Vector3d.Zero);
            var poses = new List<UnityPose>();
            for (var i = 0; i < views; i++) poses.Add(pose);
            var consumer = new RecordingConsumer();
            CaptureRunner.RunBlocking(target, poses, options, consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(views));
            return consumer.Views;
        }

        /// <summary>The pixel (column, row from the bottom) where a point (x, y) at eye depth <paramref name="depth"/> appears.</summary>
        static (int x, int y) PixelOf(double x, double y, double depth)
        {
            var focal = Size / 2.0 / Math.Tan(FovDegrees * Math.PI / 360.0);
            return ((int)Math.Floor(Size / 2.0 + focal * x / depth), (int)Math.Floor(Size / 2.0 + focal * y / depth));
        }

        static GameObject Child(GameObject parent, PrimitiveType type, string name, Vector3 position, float scale)
        {
            var child = GameObject.CreatePrimitive(type);
            child.name = name;
            child.transform.SetParent(parent.transform, false);
            child.transform.localPosition = position;
            child.transform.localScale = Vector3.one * scale;
            return child;
        }

        /// <summary>
        /// An Animator or a Timeline activation track switches renderers and objects on and off per view. The data
        /// passes must follow, as the colour pass does: a cube at the centre whose renderer is on in view 0 and off in
        /// view 1, and a second one whose object is inactive until view 2.
        /// </summary>
        [Test]
        public void RenderersSwitchedBeforeAViewAreInItsDataPassesExactlyWhenTheyAreInItsColour()
        {
            var target = new GameObject("Switched target");
            Child(target, PrimitiveType.Sphere, "Anchor", new Vector3(0, -0.8f, 0), 0.2f); // always on: the target stays capturable
            Child(target, PrimitiveType.Cube, "Switched", Vector3.zero, 1f).GetComponent<Renderer>().enabled = false;
            Child(target, PrimitiveType.Cube, "Activated", Vector3.zero, 1f).SetActive(false);

            var views = Capture(target, 3, (root, index) =>
            {
                var copy = root.transform.Find("Switched target");
                copy.Find("Switched").GetComponent<Renderer>().enabled = index == 0;
                copy.Find("Activated").gameObject.SetActive(index == 2);
            });

            const int c = Size / 2;
            foreach (var index in new[] { 0, 2 })
            {
                Assert.That(views[index].AlphaAt(c, c), Is.EqualTo(1f).Within(1e-3f), $"view {index}: the cube is in the colour pass");
                Assert.That(views[index].MaskAt(c, c), Is.EqualTo(255), $"view {index}: and in the mask");
                Assert.That(views[index].DepthAt(c, c), Is.EqualTo(CameraDistance - 0.5).Within(1e-3), $"view {index}: and in the depth (front face)");
                Assert.That(views[index].NormalAt(c, c, out _).Z, Is.LessThan(-0.99), $"view {index}: and in the normals");
            }
            Assert.That(views[1].AlphaAt(c, c), Is.EqualTo(0f).Within(1e-3f), "view 1: no cube in the colour pass");
            Assert.That(views[1].MaskAt(c, c), Is.EqualTo(0), "view 1: nor in the mask");
            Assert.That(views[1].DepthAt(c, c), Is.EqualTo(0f), "view 1: nor in the depth");
            var (ax, ay) = PixelOf(0, -0.8, CameraDistance); // the anchor's centre: its silhouette's radius is 1.5 px
            Assert.That(views[1].MaskAt(ax, ay), Is.EqualTo(255), "view 1: the anchor is still there");
            Assert.That(target.transform.Find("Switched").GetComponent<Renderer>().enabled, Is.False, "the user's objects are untouched");
        }

        /// <summary>
        /// A skinned unit cube (one bone, Unity's cube mesh, bind pose = identity) whose bone a dynamic capture moves
        /// before each view: 0.6 to the left in view 0, 0.6 to the right in view 1, both rendered in the same editor
        /// update. Unity skins once per update unless the renderer recalculates per render, so without that view 1
        /// would show view 0's pose. Colour, mask, depth and normal must all show each view's own pose.
        /// </summary>
        [Test]
        public void ASkinnedMeshPosedBeforeEachViewShowsThatViewsPoseInEveryPass()
        {
            var target = new GameObject("Skinned target");
            var body = new GameObject("Body", typeof(SkinnedMeshRenderer));
            body.transform.SetParent(target.transform, false);
            var bone = new GameObject("Bone").transform;
            bone.SetParent(body.transform, false);
            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            var mesh = Object.Instantiate(cube.GetComponent<MeshFilter>().sharedMesh);
            Own(mesh);
            var material = cube.GetComponent<MeshRenderer>().sharedMaterial; // the pipeline's default material (an asset)
            Object.DestroyImmediate(cube);
            mesh.boneWeights = Enumerable.Repeat(new BoneWeight { boneIndex0 = 0, weight0 = 1 }, mesh.vertexCount).ToArray();
            mesh.bindposes = new[] { bone.worldToLocalMatrix * body.transform.localToWorldMatrix };
            var skinned = body.GetComponent<SkinnedMeshRenderer>();
            skinned.bones = new[] { bone };
            skinned.rootBone = bone; // the bounds follow the bone
            skinned.sharedMesh = mesh;
            skinned.localBounds = mesh.bounds;
            skinned.sharedMaterial = material;

            const double shift = 0.6, frontDepth = CameraDistance - 0.5;
            var views = Capture(target, 2, (root, index) =>
                root.transform.Find("Skinned target/Body/Bone").localPosition = new Vector3(index == 0 ? -(float)shift : (float)shift, 0, 0));

            for (var index = 0; index < 2; index++)
            {
                var side = index == 0 ? -1 : 1;
                var (x, y) = PixelOf(side * shift, 0, frontDepth);
                var (ex, ey) = PixelOf(-side * shift, 0, frontDepth);
                Assert.That(views[index].AlphaAt(x, y), Is.EqualTo(1f).Within(1e-3f), $"view {index}: colour where the bone put the cube");
                Assert.That(views[index].MaskAt(x, y), Is.EqualTo(255), $"view {index}: mask there");
                Assert.That(views[index].DepthAt(x, y), Is.EqualTo(frontDepth).Within(1e-3), $"view {index}: depth there");
                Assert.That(views[index].NormalAt(x, y, out _).Z, Is.LessThan(-0.99), $"view {index}: normal there");
                Assert.That(views[index].AlphaAt(ex, ey), Is.EqualTo(0f).Within(1e-3f), $"view {index}: no colour where the other view's pose was");
                Assert.That(views[index].MaskAt(ex, ey), Is.EqualTo(0), $"view {index}: no mask there");
                Assert.That(views[index].DepthAt(ex, ey), Is.EqualTo(0f), $"view {index}: no depth there");
            }
            Assert.That(bone.localPosition, Is.EqualTo(Vector3.zero), "the user's bone is untouched");
        }
    }
}
