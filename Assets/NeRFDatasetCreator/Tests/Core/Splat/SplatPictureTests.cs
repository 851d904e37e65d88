using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.CompilerServices;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Documentation~/images/splat-placement.png is what place-splat does today: three analytic spheres (the source, in
    /// Unity's world) and a splatfacto PLY's Gaussian centres sampled on them, seen by the same camera — left as a viewer
    /// imports the PLY (an identity Transform: the centres sit in nerfstudio's dataparser frame), right through the
    /// object_to_world place-splat prints, where they sit on the spheres. Rendered by the analytic ray tracer; the
    /// centres are dots, hidden behind a sphere when the tracer says so. After a deliberate change, rewrite the file with
    /// <c>NERF_DATASET_WRITE_DOC_IMAGES=1 dotnet test Tests/Core.Tests --filter "FullyQualifiedName~SplatPicture"</c>.
    /// </summary>
    [TestFixture]
    public class SplatPictureTests
    {
        const int Width = 320, Height = 240, Gap = 8;

        static AnalyticScene Source()
        {
            var c = SplatFixtures.TargetCentreUnity;
            var scene = new AnalyticScene();
            scene.Spheres.Add(new AnalyticScene.Sphere { Centre = c + new Vector3d(-0.3, 0, 0), Radius = 0.35, Colour = new[] { 0.8, 0.25, 0.1 } });
            scene.Spheres.Add(new AnalyticScene.Sphere { Centre = c + new Vector3d(0.35, 0.2, 0.1), Radius = 0.25, Colour = new[] { 0.2, 0.4, 0.9 } });
            scene.Spheres.Add(new AnalyticScene.Sphere { Centre = c + new Vector3d(0.05, 0.5, -0.25), Radius = 0.2, Colour = new[] { 0.25, 0.7, 0.3 } });
            return scene;
        }

        /// <summary>Points on every sphere (a Fibonacci lattice), in Unity's world.</summary>
        static List<Vector3d> CentresUnity(AnalyticScene scene)
        {
            var points = new List<Vector3d>();
            foreach (var s in scene.Spheres)
            {
                var n = (int)(700 * s.Radius);
                for (var i = 0; i < n; i++)
                {
                    var z = 1 - 2 * (i + 0.5) / n;
                    var r = Math.Sqrt(1 - z * z);
                    var phi = i * Math.PI * (3 - Math.Sqrt(5));
                    points.Add(s.Centre + s.Radius * new Vector3d(r * Math.Cos(phi), z, r * Math.Sin(phi)));
                }
            }
            return points;
        }

        [Test]
        public void TheDocumentationPictureIsWhatPlaceSplatDoes()
        {
            var scene = Source();
            var unity = CentresUnity(scene);
            SplatPlacement placement;
            List<Vector3d> ply;
            using (var temp = new TempFolder())
            {
                var dataset = SplatFixtures.WriteDataset(temp.Combine("dataset"));
                var run = temp.Combine("run");
                SplatFixtures.NerfstudioRun(run, unity.Select(SplatFixtures.Normalisation.ApplyToUnityPoint).Select(SplatFixtures.ToNerfstudio).ToList(), Path.Combine(run, "exports"));
                placement = SplatPlacer.Place(dataset, run, writeCameras: false);
                ply = GaussianPly.ReadCentres(placement.PlyPath, 0).Centres.ToList();
            }
            var m = Matrix4x4d.FromRowMajor(placement.ObjectToWorld);
            var canvas = new RgbCanvas(2 * Width + Gap, Height, new byte[] { 255, 255, 255 });
            Panel(canvas, 0, scene, ply, "AS IMPORTED");
            Panel(canvas, Width + Gap, scene, ply.Select(m.MultiplyPoint).ToList(), "PLACED BY PLACE-SPLAT");

            var path = Path.Combine(RepositoryRoot(), "Documentation~", "images", "splat-placement.png");
            if (Environment.GetEnvironmentVariable("NERF_DATASET_WRITE_DOC_IMAGES") == "1")
            {
                File.WriteAllBytes(path, PngWriter.Encode(canvas.Pixels, canvas.Width, canvas.Height, PngPixelFormat.Rgb8));
                TestContext.WriteLine("wrote " + path);
            }
            var committed = PngReader.Decode(File.ReadAllBytes(path), path);
            Assert.That(new[] { committed.Width, committed.Height, committed.Channels }, Is.EqualTo(new[] { canvas.Width, canvas.Height, 3 }), path);
            var worst = 0;
            for (var p = 0; p < canvas.Pixels.Length; p++) worst = Math.Max(worst, Math.Abs(canvas.Pixels[p] - committed.Samples[p]));
            Assert.That(worst, Is.LessThanOrEqualTo(1), path + " no longer shows what place-splat does; rewrite it with NERF_DATASET_WRITE_DOC_IMAGES=1 (see this test's summary).");
        }

        /// <summary>The spheres ray-traced from one camera, the centres as dark dots where the tracer sees them.</summary>
        static void Panel(RgbCanvas canvas, int left, AnalyticScene scene, IReadOnlyList<Vector3d> centres, string label)
        {
            var target = SplatFixtures.TargetCentreUnity + new Vector3d(0, 0.1, 0);
            var eye = target + new Vector3d(1.2, 0.9, -2.6);
            var forward = (target - eye).Normalized();
            var right = Vector3d.Cross(Vector3d.UnitY, forward).Normalized(); // Unity: right = up × forward
            var up = Vector3d.Cross(forward, right);
            var tan = Math.Tan(25 * Math.PI / 180);
            var light = new Vector3d(0.4, 0.8, -0.5).Normalized();
            for (var y = 0; y < Height; y++)
                for (var x = 0; x < Width; x++)
                {
                    var sx = ((x + 0.5) / Width * 2 - 1) * tan * Width / Height;
                    var sy = (1 - (y + 0.5) / Height * 2) * tan;
                    var d = (forward + sx * right + sy * up).Normalized();
                    byte[] rgb;
                    if (scene.Trace(eye, d, 0, out _, out var normal, out var colour, out _))
                    {
                        var shade = 0.45 + 0.55 * Math.Max(0, Vector3d.Dot(normal, light));
                        rgb = colour.Select(v => Srgb.EncodeByteExact(v * shade)).ToArray();
                    }
                    else rgb = new byte[] { 236, 236, 236 };
                    canvas.Set(left + x, y, rgb);
                }
            var dot = new byte[] { 25, 25, 25 };
            foreach (var c in centres)
            {
                var v = c - eye;
                var depth = Vector3d.Dot(v, forward);
                if (!(depth > 1e-3)) continue;
                var px = (Vector3d.Dot(v, right) / depth / (tan * Width / Height) + 1) / 2 * Width;
                var py = (1 - Vector3d.Dot(v, up) / depth / tan) / 2 * Height;
                if (px < 1 || py < 1 || px > Width - 2 || py > Height - 2) continue;
                // Hidden when the tracer hits something clearly before the centre (a centre on the visible side is not).
                if (scene.Trace(eye, v.Normalized(), 0, out var t, out _, out _, out _) && t < v.Length - 1e-3) continue;
                canvas.Clip(left, 0, left + Width, Height);
                canvas.FillDisc(left + px, py, 1.3, dot);
                canvas.ResetClip();
            }
            canvas.Text(left + 6, 6, label, new byte[] { 20, 20, 20 });
        }

        static string RepositoryRoot([CallerFilePath] string path = "")
        {
            var folder = Path.GetDirectoryName(path);
            while (folder != null && !Directory.Exists(Path.Combine(folder, "Documentation~"))) folder = Path.GetDirectoryName(folder);
            return folder ?? throw new DirectoryNotFoundException("Documentation~ above " + path);
        }
    }
}
