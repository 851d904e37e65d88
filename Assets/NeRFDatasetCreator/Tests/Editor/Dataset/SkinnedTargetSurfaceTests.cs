using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// A skinned cube (Unity's primitive cube mesh, one bone, in its bind pose) whose renderer sits under a parent
    /// scaled by 0.01 — what an FBX character imported in centimetres looks like — and carries a scale of its own.
    /// In the bind pose the skinned vertices are exactly where a MeshFilter would put them:
    /// renderer.localToWorldMatrix × vertex. A scale applied twice (or not at all) moves every vertex.
    /// </summary>
    [TestFixture]
    public class SkinnedTargetSurfaceTests
    {
        GameObject _parent;
        Mesh _mesh;

        [TearDown]
        public void Destroy()
        {
            if (_parent != null) Object.DestroyImmediate(_parent);
            if (_mesh != null) Object.DestroyImmediate(_mesh);
        }

        /// <summary>The character: its parent at (1, 2, 3) turned 30°, scale 0.01; the cube's world side is 0.02.</summary>
        SkinnedMeshRenderer BuildCharacter()
        {
            _parent = new GameObject("Character (0.01)");
            _parent.transform.SetPositionAndRotation(new Vector3(1, 2, 3), Quaternion.Euler(0, 30, 0));
            _parent.transform.localScale = Vector3.one * 0.01f;
            var body = new GameObject("Body", typeof(SkinnedMeshRenderer));
            body.transform.SetParent(_parent.transform, false);
            body.transform.localPosition = new Vector3(0, 50, 0);
            body.transform.localScale = new Vector3(2, 2, 2);
            var bone = new GameObject("Root bone").transform;
            bone.SetParent(body.transform, false);
            bone.localPosition = new Vector3(0.25f, 0, 0);

            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            _mesh = Object.Instantiate(cube.GetComponent<MeshFilter>().sharedMesh);
            var material = cube.GetComponent<MeshRenderer>().sharedMaterial; // Unity's default material: an asset, it outlives the cube
            Object.DestroyImmediate(cube);
            _mesh.boneWeights = Enumerable.Repeat(new BoneWeight { boneIndex0 = 0, weight0 = 1 }, _mesh.vertexCount).ToArray();
            var renderer = body.GetComponent<SkinnedMeshRenderer>();
            // The bind pose as Unity's importer writes it: the bone's world-to-local times the mesh's local-to-world.
            _mesh.bindposes = new[] { bone.worldToLocalMatrix * body.transform.localToWorldMatrix };
            renderer.bones = new[] { bone };
            renderer.rootBone = bone;
            renderer.sharedMesh = _mesh;
            renderer.sharedMaterial = material; // TargetSurface samples the submeshes that have a material

            return renderer;
        }

        [Test]
        public void ASkinnedMeshUnderACentimetreParentLiesOnItsRenderedSurface()
        {
            var body = BuildCharacter().gameObject;
            var warnings = new List<ValidationProblem>();
            var surface = TargetSurface.Collect(_parent, warnings);
            Assert.That(warnings, Is.Empty);
            Assert.That(surface, Has.Count.EqualTo(1));
            var local = _mesh.vertices;
            var toWorld = body.transform.localToWorldMatrix;
            Assert.That(surface[0].Vertices, Has.Count.EqualTo(local.Length));
            for (var i = 0; i < local.Length; i++)
            {
                var expected = toWorld.MultiplyPoint3x4(local[i]);
                var actual = surface[0].Vertices[i];
                Assert.That(new[] { actual.X, actual.Y, actual.Z }, Is.EqualTo(new double[] { expected.x, expected.y, expected.z }).Within(1e-5),
                    "vertex " + i + " (the cube's side is 0.02 in the world; a doubled scale gives 0.0004, none gives 1)");
            }
            // The world cube's area: 6 faces of side 1 × 2 × 0.01 = 0.02.
            var area = Enumerable.Range(0, surface[0].TriangleCount).Sum(t => surface[0].TriangleArea(t));
            Assert.That(area, Is.EqualTo(6 * 0.02 * 0.02).Within(1e-7));
        }

        [Test]
        public void ADynamicCaptureMeasuresASkinnedMeshUnderACentimetreParentAtItsRenderedSize()
        {
            var body = BuildCharacter().gameObject;
            var project = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "nerf-skinned-bounds-" + System.Guid.NewGuid().ToString("N"));
            System.IO.Directory.CreateDirectory(project);
            try
            {
                // A dynamic capture measures the target's bounds on posed copies (TimeMeasurement.PosedBounds), skinned
                // meshes by BakeMesh: nothing animates here, so they are the bind-pose cube's.
                var s = new DatasetSettings { Name = "character", Width = 32, Height = 32, Supersampling = 1, Seed = 1 };
                s.Loaders = TargetLoaders.GaussianSplatting;
                s.Train.Count = 4;
                s.Val.Count = 0;
                s.Test.Count = 0;
                s.Time.Mode = TimeMode.MultiView;
                s.Time.EndAtClipLength = false;
                s.Time.EndSeconds = 1;
                s.Time.Steps = 2;
                var prepared = DatasetCapture.Prepare(s, _parent, project);
                Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
                var centre = body.transform.position;
                Assert.That(prepared.Plan.Target.Centre.X, Is.EqualTo(centre.x).Within(1e-4));
                Assert.That(prepared.Plan.Target.Centre.Y, Is.EqualTo(centre.y).Within(1e-4));
                Assert.That(prepared.Plan.Target.Centre.Z, Is.EqualTo(centre.z).Within(1e-4));
                // The world cube of side 0.02 turned 30° about y: its axis-aligned box is 0.02 (cos 30° + sin 30°) wide in x
                // and z, 0.02 high; the radius is that box's half-diagonal. Without the scale it would be 100 times larger.
                var w = 0.01 * (System.Math.Cos(System.Math.PI / 6) + System.Math.Sin(System.Math.PI / 6));
                Assert.That(prepared.Plan.Target.BoundingRadius, Is.EqualTo(System.Math.Sqrt(2 * w * w + 0.01 * 0.01)).Within(1e-4));
            }
            finally
            {
                System.IO.Directory.Delete(project, true);
            }
        }
    }
}
