using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>FlowMeshes refuses per-step meshes whose topology changes, naming the object from the PLYs' <c>comment object</c> lines.</summary>
    public class FlowMeshesTests
    {
        static readonly Vector3d[] Quad = { new Vector3d(0, 0, 0), new Vector3d(1, 0, 0), new Vector3d(1, 1, 0), new Vector3d(0, 1, 0) };

        static SurfaceMesh Mesh(string name, int[] triangles) => new SurfaceMesh(Quad, triangles, null, name: name);

        static void WritePly(string root, string file, params SurfaceMesh[] meshes)
        {
            var path = Path.Combine(root, file.Replace('/', Path.DirectorySeparatorChar));
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            using (var stream = File.Create(path)) TargetMeshPly.Write(stream, meshes);
        }

        static FlowVideo Video() => new FlowVideo("train", "train", null, new List<FlowVideoFrame>
        {
            new FlowVideoFrame(null, 0, "geometry/target_mesh_t0000.ply"),
            new FlowVideoFrame(null, 1, "geometry/target_mesh_t0001.ply"),
        });

        static string Refusal(string root) =>
            Assert.Throws<InvalidParameterException>(() => FlowMeshes.Read(root, new[] { Video() })).Message;

        [Test]
        public void AnObjectWithMoreTrianglesIsNamed()
        {
            using (var temp = new TempFolder())
            {
                WritePly(temp.Path, "geometry/target_mesh_t0000.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Cloth", new[] { 0, 1, 2 }));
                WritePly(temp.Path, "geometry/target_mesh_t0001.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Cloth", new[] { 0, 1, 2, 0, 2, 3 }));
                var message = Refusal(temp.Path);
                Assert.That(message, Does.Contain("geometry/target_mesh_t0001.ply").And.Contain("object \"Cloth\" with 2 triangles, 1 in geometry/target_mesh_t0000.ply"));
                Assert.That(message, Does.Contain("Particles are not in the geometry pack"));
            }
        }

        [Test]
        public void AnObjectWithOtherTrianglesIsNamed()
        {
            using (var temp = new TempFolder())
            {
                WritePly(temp.Path, "geometry/target_mesh_t0000.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Cloth", new[] { 0, 1, 2, 0, 2, 3 }));
                WritePly(temp.Path, "geometry/target_mesh_t0001.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Cloth", new[] { 0, 1, 2, 1, 2, 3 }));
                Assert.That(Refusal(temp.Path), Does.Contain("object \"Cloth\" with other triangles than in geometry/target_mesh_t0000.ply (triangle 1 of it differs)"));
            }
        }

        [Test]
        public void AMissingObjectIsNamed()
        {
            using (var temp = new TempFolder())
            {
                WritePly(temp.Path, "geometry/target_mesh_t0000.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Smoke", new[] { 0, 1, 2 }));
                WritePly(temp.Path, "geometry/target_mesh_t0001.ply", Mesh("Body", new[] { 0, 1, 2 }));
                Assert.That(Refusal(temp.Path), Does.Contain("has no object \"Smoke\", which geometry/target_mesh_t0000.ply has"));
            }
        }

        [Test]
        public void OneTopologyIsRead()
        {
            using (var temp = new TempFolder())
            {
                WritePly(temp.Path, "geometry/target_mesh_t0000.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Cloth", new[] { 0, 2, 3 }));
                WritePly(temp.Path, "geometry/target_mesh_t0001.ply", Mesh("Body", new[] { 0, 1, 2 }), Mesh("Cloth", new[] { 0, 2, 3 }));
                var meshes = FlowMeshes.Read(temp.Path, new[] { Video() });
                Assert.That(meshes.Triangles.Length, Is.EqualTo(6));
                Assert.That(TargetMeshObjects.Read(Path.Combine(temp.Path, "geometry", "target_mesh_t0000.ply")), Has.Count.EqualTo(2));
            }
        }
    }
}
