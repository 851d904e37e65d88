using System;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// The mask, depth and normal passes follow each material's cull mode and alpha clipping, in whichever pipeline
    /// the project uses: a cutout plane with a 2×2 hole pattern, a two-sided plane seen from behind (and a one-sided
    /// one, which must vanish). The plane is built here with known winding (clockwise = front, normal −Z) and UVs
    /// (u = x + ½, v = y + ½), so every expected pixel follows from the pinhole model alone.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class DataPassCaptureTests : GpuSceneFixture
    {
        const int Size = 64;
        const double FovDegrees = 40.0;
        const double Distance = 2.0;


        static bool UrpIsActive
        {
            get
            {
                var pipeline = GraphicsSettings.currentRenderPipeline;
                return pipeline != null && pipeline.GetType().FullName == "UnityEngine.Rendering.Universal.UniversalRenderPipelineAsset";
            }
        }

        static CaptureOptions Options() => new CaptureOptions
        {
            Width = Size,
            Height = Size,
            Supersampling = 1,
            VerticalFieldOfViewDegrees = FovDegrees,
            NearClip = 0.1,
            FarClip = 100,
            ReadbacksInFlight = 1,
        };

        /// <summary>A unit plane in z = 0 facing −Z (its front is seen from z &lt; 0).</summary>
        GameObject Plane(Material material)
        {
            var mesh = new Mesh { name = "Test plane" };
            mesh.vertices = new[] { new Vector3(-0.5f, -0.5f, 0), new Vector3(-0.5f, 0.5f, 0), new Vector3(0.5f, 0.5f, 0), new Vector3(0.5f, -0.5f, 0) };
            mesh.uv = new[] { new Vector2(0, 0), new Vector2(0, 1), new Vector2(1, 1), new Vector2(1, 0) };
            mesh.normals = new[] { Vector3.back, Vector3.back, Vector3.back, Vector3.back };
            // Clockwise as seen from −Z: Unity's front faces.
            mesh.triangles = new[] { 0, 1, 2, 0, 2, 3 };
            Own(mesh);
            var plane = new GameObject("Test plane", typeof(MeshFilter), typeof(MeshRenderer));
            plane.GetComponent<MeshFilter>().sharedMesh = mesh;
            plane.GetComponent<MeshRenderer>().sharedMaterial = material;
            return plane;
        }

        Material Owned(Material material)
        {
            Own(material);
            return material;
        }

        Material FindOrIgnore(string shaderName)
        {
            var shader = Shader.Find(shaderName);
            if (shader == null) Assert.Ignore("the shader '" + shaderName + "' is not in this project");
            return Owned(new Material(shader));
        }

        /// <summary>A 2×2 alpha checker, point-sampled: texels (0,0) and (1,1) opaque, (1,0) and (0,1) transparent.</summary>
        Texture2D Checker()
        {
            var texture = new Texture2D(2, 2, TextureFormat.RGBA32, false) { filterMode = FilterMode.Point, wrapMode = TextureWrapMode.Clamp };
            texture.SetPixels32(new[] { new Color32(255, 255, 255, 255), new Color32(255, 255, 255, 0), new Color32(255, 255, 255, 0), new Color32(255, 255, 255, 255) });
            texture.Apply(false);
            Own(texture);
            return texture;
        }

        /// <summary>The pipeline's usual cutout material: URP Lit with Alpha Clipping, or Built-in Standard in Cutout mode.</summary>
        Material Cutout(Texture2D texture)
        {
            if (UrpIsActive)
            {
                var lit = FindOrIgnore("Universal Render Pipeline/Lit");
                lit.SetTexture("_BaseMap", texture);
                lit.SetFloat("_AlphaClip", 1);
                lit.EnableKeyword("_ALPHATEST_ON"); // what URP's BaseShaderGUI does for _AlphaClip = 1
                lit.SetFloat("_Cutoff", 0.5f);
                return lit;
            }
            var standard = FindOrIgnore("Standard");
            standard.SetTexture("_MainTex", texture);
            standard.SetFloat("_Mode", 1); // Cutout, as StandardShaderGUI sets it
            standard.EnableKeyword("_ALPHATEST_ON");
            standard.SetFloat("_Cutoff", 0.5f);
            return standard;
        }

        /// <summary>Both faces: URP Lit with Render Face Both (_Cull 0), or Built-in's Cull Off cutout shader with no holes.</summary>
        Material TwoSided()
        {
            if (UrpIsActive)
            {
                var lit = FindOrIgnore("Universal Render Pipeline/Lit");
                lit.SetFloat("_Cull", 0);
                return lit;
            }
            return FindOrIgnore("Legacy Shaders/Transparent/Cutout/Soft Edge Unlit"); // white texture, alpha 1: nothing clipped
        }

        Material OneSided() => UrpIsActive ? FindOrIgnore("Universal Render Pipeline/Lit") : FindOrIgnore("Standard");

        static RecordedView CaptureFrom(GameObject target, Vector3d cameraPosition)
        {
            var consumer = new RecordingConsumer();
            var poses = new List<UnityPose> { LookAt.FromPositions(cameraPosition, Vector3d.Zero) };
            CaptureRunner.RunBlocking(target, poses, Options(), consumer, new ScriptedProgress());
            Assert.That(consumer.Views, Has.Count.EqualTo(1));
            return consumer.Views[0];
        }

        /// <summary>The pixel (column, row from the bottom) where a point of the plane z = 0 appears from (0, 0, −d) looking +Z.</summary>
        static (int x, int y) PixelOf(double x, double y)
        {
            var focal = Size / 2.0 / Math.Tan(FovDegrees * Math.PI / 360.0);
            return ((int)Math.Floor(Size / 2.0 + focal * x / Distance), (int)Math.Floor(Size / 2.0 + focal * y / Distance));
        }

        [Test]
        public void CutoutHolesHaveNoMaskAndNoDepthAndTheRestIsThePlane()
        {
            var plane = Plane(Cutout(Checker()));
            var view = CaptureFrom(plane, new Vector3d(0, 0, -Distance));
            // Quadrant centres (x, y) = (±¼, ±¼) sample texels ((x + ½)·2, (y + ½)·2): opaque where both agree.
            foreach (var (x, y, hole) in new[] { (-0.25, -0.25, false), (0.25, 0.25, false), (0.25, -0.25, true), (-0.25, 0.25, true) })
            {
                var (px, py) = PixelOf(x, y);
                var where = $"({x}, {y}) at pixel ({px}, {py})";
                if (hole)
                {
                    Assert.That(view.MaskAt(px, py), Is.EqualTo(0), "hole mask " + where);
                    Assert.That(view.DepthAt(px, py), Is.EqualTo(0f), "hole depth " + where);
                    Assert.That(view.NormalAt(px, py, out var coverage).Length, Is.EqualTo(0.0), "hole normal " + where);
                    Assert.That(coverage, Is.EqualTo(0f), "hole normal alpha " + where);
                }
                else
                {
                    Assert.That(view.MaskAt(px, py), Is.EqualTo(255), "solid mask " + where);
                    Assert.That(view.DepthAt(px, py), Is.EqualTo(Distance).Within(1e-3), "solid depth " + where);
                }
            }
        }

        [Test]
        public void ATwoSidedPlaneSeenFromBehindIsPresentWithItsNormalTowardsTheCamera()
        {
            var plane = Plane(TwoSided());
            var view = CaptureFrom(plane, new Vector3d(0, 0, Distance)); // behind: the plane's front faces −Z
            Assert.That(view.MaskAt(Size / 2, Size / 2), Is.EqualTo(255), "mask");
            Assert.That(view.DepthAt(Size / 2, Size / 2), Is.EqualTo(Distance).Within(1e-3), "depth");
            var normal = view.NormalAt(Size / 2, Size / 2, out var coverage);
            Assert.That(coverage, Is.EqualTo(1f));
            Assert.That(normal.Z, Is.GreaterThan(0.99), "the back face's normal is turned to +Z, towards the camera: " + normal);
        }

        [Test]
        public void ATwoSidedPlaneSeenFromTheFrontKeepsItsOwnNormal()
        {
            var plane = Plane(TwoSided());
            var view = CaptureFrom(plane, new Vector3d(0, 0, -Distance));
            var normal = view.NormalAt(Size / 2, Size / 2, out _);
            Assert.That(normal.Z, Is.LessThan(-0.99), "front face normal −Z: " + normal);
        }

        [Test]
        public void AOneSidedPlaneSeenFromBehindIsAbsentFromEveryDataPass()
        {
            var plane = Plane(OneSided());
            var view = CaptureFrom(plane, new Vector3d(0, 0, Distance));
            Assert.That(view.MaskAt(Size / 2, Size / 2), Is.EqualTo(0), "mask");
            Assert.That(view.DepthAt(Size / 2, Size / 2), Is.EqualTo(0f), "depth");
            // And from the front it is there: the test above is about culling, not a plane that never draws.
            var front = CaptureFrom(plane, new Vector3d(0, 0, -Distance));
            Assert.That(front.MaskAt(Size / 2, Size / 2), Is.EqualTo(255));
        }

        [Test]
        public void AMirroredSphereStillShowsItsNearSide()
        {
            // Negative scale flips the winding; Unity flips culling with it for renderers it draws.
            var sphere = TestScene.LitSphere("Mirrored sphere");
            sphere.transform.localScale = new Vector3(-1, 1, 1);
            var view = CaptureFrom(sphere, new Vector3d(0.3, 0.2, -3));
            var depth = view.DepthAt(Size / 2, Size / 2);
            var d = Math.Sqrt(0.3 * 0.3 + 0.2 * 0.2 + 9);
            Assert.That(depth, Is.EqualTo(d - 0.5).Within(0.01 * (d - 0.5)), "near side at d − r, not the far side at d + r");
        }

        /// <summary>
        /// URP's hardest renderer set-up for the data passes: Depth Priming Forced (the prepass draws only DepthOnly /
        /// DepthNormals passes, then opaques draw with ZTest Equal, ZWrite Off), MSAA 4× and SSAO drawn after opaques.
        /// The data passes do not go through URP, so they must come out as in the Built-in pipeline; the colour pass
        /// must still show the sphere.
        /// </summary>
        [Test]
        public void UnderUrpWithDepthPrimingForcedMsaaAndSsaoTheDataPassesAreUnchanged()
        {
            if (!UrpIsActive)
                Assert.Ignore("URP is not the active render pipeline (" + CaptureEnvironment.RenderPipelineName +
                              "): run this in a URP project (Tests/ has one) to test URP's renderer settings.");
            using (var urp = UrpRendererOverride.Apply(depthPrimingForced: true, msaaSamples: 4, addSsaoAfterOpaque: true))
            {
                var sphere = TestScene.LitSphere("URP sphere");
                const double d = 3.0;
                var view = CaptureFrom(sphere, new Vector3d(0, 0, -d));
                Assert.That(view.MaskAt(Size / 2, Size / 2), Is.EqualTo(255), "mask centre");
                Assert.That(view.MaskAt(0, 0), Is.EqualTo(0), "mask corner");
                Assert.That(view.DepthAt(Size / 2, Size / 2), Is.EqualTo(d - 0.5).Within(0.01 * (d - 0.5)), "depth");
                var normal = view.NormalAt(Size / 2, Size / 2, out _);
                Assert.That(normal.Z, Is.LessThan(-0.99), "normal towards the camera at −Z: " + normal);
                var lit = view.ColorAt(Size / 2, Size / 2, 0) + view.ColorAt(Size / 2, Size / 2, 1) + view.ColorAt(Size / 2, Size / 2, 2);
                Assert.That(lit, Is.GreaterThan(0), "the colour pass still draws the sphere");
            }
        }
    }
}
