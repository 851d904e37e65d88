using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Review R4-7: the target is picked below its LODGroup ("Building/Target"); the group on "Building" lists the
    /// target's sphere as LOD 0 and its cube (at x = 5) as LOD 1. The posed copies of the dynamic capture
    /// (<see cref="TargetSurfaceOverTime"/>, the same <c>SceneCopy.OfObject</c> as the start surface and the posed bounds)
    /// copy the target alone, without the group above it: they read the LOD 0 sphere only, as the capture's images do.
    /// Before the fix the cube was read too (2 meshes, centre near x = 2.5).
    /// </summary>
    [TestFixture]
    public class LodAboveTargetCopyTests
    {
        Scene _scene;

        [SetUp]
        public void SetUp() => _scene = TestScene.Open();

        [TearDown]
        public void TearDown() => TestScene.Close(_scene);

        [Test]
        public void APosedCopyOfATargetBelowItsLodGroupReadsLod0Only()
        {
            var building = new GameObject("Building");
            var target = new GameObject("Target");
            target.transform.SetParent(building.transform, false);
            var sphere = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            sphere.transform.SetParent(target.transform, false);
            var cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            cube.transform.SetParent(target.transform, false);
            cube.transform.localPosition = new Vector3(5, 0, 0);
            building.AddComponent<LODGroup>().SetLODs(new[]
            {
                new LOD(0.5f, new Renderer[] { sphere.GetComponent<Renderer>() }),
                new LOD(0.01f, new Renderer[] { cube.GetComponent<Renderer>() }),
            });
            // The user's target as it stands: LodZero already sees the group above it.
            Assert.That(TargetSurface.Collect(target, new List<ValidationProblem>()), Has.Count.EqualTo(1));

            var warnings = new List<ValidationProblem>();
            using (var steps = new TargetSurfaceOverTime(target, new TimeRange(TimeMode.Monocular, TimeSources.All, 0, 1, 2, 0), 1, warnings))
            {
                var meshes = steps.At(1);
                Assert.That(meshes, Has.Count.EqualTo(1), "the LOD 1 cube is not part of the posed copy's surface");
                // The sphere at the origin (its UV seam's duplicated vertices may pull the mean a little; the LOD 1 cube
                // at x = 5 would be one mesh more and, merged, pull it past 0.2).
                Assert.That(meshes[0].Vertices.Average(v => v.X), Is.EqualTo(0).Within(0.1), "the sphere at the origin");
                Assert.That(meshes[0].Vertices.Max(v => v.X), Is.LessThan(0.51), "nothing of the cube");
            }
            Assert.That(cube.GetComponent<Renderer>().enabled, Is.True, "the user's renderer is untouched");
        }
    }
}
