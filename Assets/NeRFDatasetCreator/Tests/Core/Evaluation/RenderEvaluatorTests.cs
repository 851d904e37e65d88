using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Whole evaluations of an analytically rendered sphere (<see cref="AnalyticSphereDataset"/>): renders made from the
    /// same exact pixels with a known perturbation, the figures computed independently here from those pixels.
    /// </summary>
    public class RenderEvaluatorTests
    {
        const int W = 48, H = 40;

        static EvaluationOptions Options(string dataset, string renders) => new EvaluationOptions { DatasetFolder = dataset, RendersFolder = renders, Threads = 2 };

        [Test]
        public void PerturbedRendersScoreTheirIndependentlyComputedPsnrAndSsim()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                var renders = temp.Combine("shots");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 10 + 5 * i), W, H, PngPixelFormat.Rgb8));

                var result = RenderEvaluator.Run(Options(dataset, renders));
                Assert.That(result.Renders.Layout, Is.EqualTo(RenderLayout.Plain));
                Assert.That(result.Views.Count, Is.EqualTo(3));
                for (var i = 0; i < views.Count; i++)
                {
                    var truth = AnalyticSphereDataset.Render(views[i], W, H, 0).Select(b => b / 255f).ToArray();
                    var render = AnalyticSphereDataset.Render(views[i], W, H, 10 + 5 * i).Select(b => b / 255f).ToArray();
                    double sum = 0, inside = 0, insideCount = 0;
                    for (var k = 0; k < truth.Length; k++)
                    {
                        double d = render[k] - truth[k];
                        sum += d * d;
                        if (views[i].Mask[k / 3] == 255) { inside += d * d; insideCount++; }
                    }
                    var view = result.Views[i];
                    Assert.That(view.Psnr, Is.EqualTo(-10 * Math.Log10(sum / truth.Length)).Within(1e-9));
                    Assert.That(view.MaskedPsnr, Is.EqualTo(-10 * Math.Log10(inside / insideCount)).Within(1e-9));
                    Assert.That(view.Ssim, Is.EqualTo(ImageMetricsTests.Direct3dgs(render, truth, W, H, 3)).Within(1e-6));
                    Assert.That(view.MaskedPsnr, Is.LessThan(view.Psnr), "the error is all inside the target");
                }
                Assert.That(result.Views[0].Psnr, Is.GreaterThan(result.Views[2].Psnr), "a larger perturbation scores lower");

                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", "metrics.json")));
                Assert.That((string)metrics["generator"], Is.EqualTo(MetricsJson.Generator));
                Assert.That((double)metrics["mean"]["psnr"], Is.EqualTo(result.Views.Average(v => v.Psnr)).Within(1e-9));
                Assert.That((string)metrics["views"][1]["error_map"], Is.EqualTo("errors/r_1_error.png"));
                Assert.That(metrics["definitions"]["lpips"].ToString(), Does.Contain("metrics.py"));
                var errorMap = PngReader.Read(Path.Combine(renders, "evaluation-test", "errors", "r_1_error.png"));
                Assert.That((errorMap.Width, errorMap.Height, errorMap.Channels), Is.EqualTo((W, H, 3)));
                var html = File.ReadAllText(Path.Combine(renders, "evaluation-test", "report.html"));
                Assert.That(html, Does.Contain("<svg").And.Contain("data:image/png;base64,").And.Not.Contain("src=\"http"));
                Assert.That(html.Split(new[] { "data:image/png;base64," }, StringSplitOptions.None).Length - 1, Is.EqualTo(9), "ground truth, render and error for each of 3 views");
            }
        }

        [Test]
        public void DepthAndNormalRendersAreScoredOnTheMask()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                var renders = temp.Combine("plain");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                {
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 0), W, H, PngPixelFormat.Rgb8));
                    // Depth 10 % too far; normals exact.
                    var depth = views[i].Depth.Select(d => (ushort)Math.Round(d * 1.1)).ToArray();
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + "_depth_0000.png"), PngWriter.EncodeGray16(depth, W, H));
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + "_normal_0000.png"), PngWriter.Encode(views[i].Normals, W, H, PngPixelFormat.Rgb8));
                }
                var result = RenderEvaluator.Run(Options(dataset, renders));
                foreach (var view in result.Views)
                {
                    Assert.That(view.Psnr, Is.EqualTo(double.PositiveInfinity), "the colour is the ground truth itself");
                    Assert.That(view.Depth.AbsRel, Is.EqualTo(0.1).Within(2e-4), "rounding to thousandths at z ≈ 3–4");
                    Assert.That(view.Depth.Delta125, Is.EqualTo(1));
                    Assert.That(view.Depth.Rmse, Is.GreaterThan(0.3).And.LessThan(0.4), "0.1 × z with z between 3 and 4");
                    Assert.That(view.Depth.Pixels, Is.EqualTo(view.MaskPixels));
                    Assert.That(view.Normals.MeanDegrees, Is.EqualTo(0).Within(1e-5), "acos of a float dot product of 1");
                }
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", "metrics.json")));
                Assert.That(metrics["mean"]["psnr"].Type, Is.EqualTo(JTokenType.Null), "no finite PSNR to average");
                Assert.That(metrics["views"][0]["psnr"].Type, Is.EqualTo(JTokenType.Null), "∞ is written as null");
                Assert.That((int)metrics["mean"]["identical_views"], Is.EqualTo(3));
                Assert.That((double)metrics["mean"]["depth"]["abs_rel"], Is.EqualTo(0.1).Within(2e-4));
            }
        }

        /// <summary>
        /// Keys only, as check: on a nerf_synthetic-style split whose frames name no pass files, the 8-bit
        /// <c>r_&lt;i&gt;_depth_0000.png</c> pictures beside the images are not taken for depth (evaluate used to guess them
        /// and stop with "… is not a 16-bit grey depth PNG"): the colour is scored, depth and normals are skipped with a note.
        /// </summary>
        [Test]
        public void ANerfSyntheticStyleSplitScoresColourAndSkipsThePassesItsFramesDoNotName()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H);
                AnalyticSphereDataset.MakeNerfSyntheticStyle(dataset, "test", views, W, H);
                var renders = temp.Combine("plain");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                {
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 10), W, H, PngPixelFormat.Rgb8));
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + "_depth_0000.png"), PngWriter.EncodeGray16(views[i].Depth, W, H));
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + "_normal_0000.png"), PngWriter.Encode(views[i].Normals, W, H, PngPixelFormat.Rgb8));
                }
                Assert.That(PngInfo.Read(Path.Combine(dataset, "test", "r_0_depth_0000.png")).BitDepth, Is.EqualTo(8), "the picture beside the image is not depth");

                var result = RenderEvaluator.Run(Options(dataset, renders));

                Assert.That(result.Views.Count, Is.EqualTo(3));
                foreach (var view in result.Views)
                {
                    Assert.That(view.Psnr, Is.GreaterThan(20).And.LessThan(double.PositiveInfinity), "the colour is scored");
                    Assert.That(view.Ssim, Is.GreaterThan(0.5).And.LessThan(1));
                    Assert.That(view.Depth, Is.Null, "depth is not scored");
                    Assert.That(view.Normals, Is.Null, "normals are not scored");
                }
                Assert.That(result.Notes, Has.Some.EqualTo("The renders include depth, but the frames of the dataset's test split name no depth file (depth_path; files are never guessed from the image names): depth not scored."));
                Assert.That(result.Notes, Has.Some.EqualTo("The renders include normals, but the frames of the dataset's test split name no normal file (normal_path; files are never guessed from the image names): normals not scored."));
                var metrics = JObject.Parse(File.ReadAllText(Path.Combine(renders, "evaluation-test", "metrics.json")));
                Assert.That((double)metrics["mean"]["psnr"], Is.EqualTo(result.Views.Average(v => v.Psnr)).Within(1e-9));
                Assert.That(metrics["mean"]["depth"], Is.Null);
                Assert.That(metrics["notes"].Select(n => (string)n), Has.Some.Contains("name no depth file (depth_path"));
                Assert.That(File.ReadAllText(Path.Combine(renders, "evaluation-test", "report.html")), Does.Contain("name no depth file (depth_path"));
            }
        }

        [Test]
        public void GeometryIsScoredAgainstTheGeometryPacksObservedPoints()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, 96, 80, train: 8);
                var renders = temp.Combine("plain");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], 96, 80, 3), 96, 80, PngPixelFormat.Rgb8));
                // The reconstruction: a sphere 3 % too large, as an OBJ mesh.
                var recon = AnalyticSphereDataset.UvSphere(1.03, 32, 64);
                var obj = temp.Combine("recon.obj");
                File.WriteAllLines(obj, recon.Vertices.Select(v => FormattableString.Invariant($"v {v.X} {v.Y} {v.Z}"))
                    .Concat(Enumerable.Range(0, recon.TriangleCount).Select(t => $"f {recon.Triangles[3 * t] + 1} {recon.Triangles[3 * t + 1] + 1} {recon.Triangles[3 * t + 2] + 1}")));
                var options = Options(dataset, renders);
                options.GeometryPath = obj;
                options.TruthPoints = 100000;
                var result = RenderEvaluator.Run(options);
                var g = result.Geometry;
                Assert.That(g.TruthSource, Does.Contain("geometry pack"));
                Assert.That(g.Distances.Threshold, Is.EqualTo(0.005 * 2 * Math.Sqrt(3)).Within(1e-3), "0.5 % of the unit sphere's box diagonal 2√3");
                Assert.That(g.Distances.Accuracy, Is.EqualTo(0.03).Within(0.004));
                Assert.That(g.Distances.Completeness, Is.EqualTo(0.03).Within(0.004));
                Assert.That(g.Distances.FScore, Is.EqualTo(0), "0.03 is beyond the 0.017 threshold everywhere");
                // A camera at distance 4 sees the unit sphere within acos(1/4) = 75.5° of its direction; eight cameras at
                // ±30° elevation, 45° apart, leave no point further than 60° from one of them: all are observed.
                Assert.That(g.Distances.ObservedTruthPoints, Is.EqualTo(g.Distances.TruthPoints));
                Assert.That(g.TrainViewsUsed, Is.EqualTo(8));

                var loose = Options(dataset, renders);
                loose.GeometryPath = obj;
                loose.TruthPoints = 100000;
                loose.Threshold = 0.05;
                loose.OutFolder = temp.Combine("loose");
                Assert.That(RenderEvaluator.Run(loose).Geometry.Distances.FScore, Is.GreaterThan(0.99));
            }
        }

        [Test]
        public void TheGeometryPackLinesUpWithTheDepthMaps()
        {
            using (var temp = new TempFolder())
            {
                const int w = 320, h = 256;
                var dataset = temp.Combine("sphere");
                AnalyticSphereDataset.Write(dataset, w, h, train: 2, test: 1);
                var mesh = GeometryFile.Read(Path.Combine(dataset, TargetMeshPly.RelativePath));
                var points = GeometryEvaluation.ToFloats(SurfaceSampler.Sample(new[] { mesh }, 20000, 5));
                var train = EvaluationDataset.Read(dataset, "train");
                var frame = train.Frames[0];
                var depth = EvaluationImages.DepthPng(PngReader.Read(frame.DepthPath), train.DepthScale, frame.DepthPath);
                var eye = frame.CameraToWorld.Translation;
                int Facing(float[] cloud, bool[] flags, out int seen)
                {
                    // Points facing the camera at most 60° off its ray: within a pixel (0.007 units here) the surface
                    // moves at most tan 60° × 0.007 in depth, so they agree with the depth map to 0.012 + the faceting.
                    int facing = 0;
                    seen = 0;
                    for (var p = 0; p < flags.Length; p++)
                    {
                        var x = new Vector3d(cloud[3 * p], cloud[3 * p + 1], cloud[3 * p + 2]);
                        if (Vector3d.Dot(x.Normalized(), (eye - x).Normalized()) < 0.5) continue;
                        facing++;
                        if (flags[p]) seen++;
                    }
                    return facing;
                }
                var flagsAtTruth = new bool[points.Length / 3];
                var marked = ObservedPoints.Mark(points, flagsAtTruth, frame.CameraToWorld, depth, w, h, train.Focal(w), w / 2.0, h / 2.0, 0.012, 0);
                var facingCount = Facing(points, flagsAtTruth, out var facingSeen);
                Assert.That(facingSeen, Is.GreaterThan(0.99 * facingCount), "the mesh and the depth maps are in one frame and one unit");
                Assert.That(marked, Is.LessThan(points.Length / 3 / 2), "the far side is hidden");

                // The same points 0.05 along the camera's axis are not on the depth maps' surface.
                var axis = frame.CameraToWorld.Column(2);
                var moved = (float[])points.Clone();
                for (var p = 0; p < moved.Length; p += 3) { moved[p] += (float)(0.05 * axis.X); moved[p + 1] += (float)(0.05 * axis.Y); moved[p + 2] += (float)(0.05 * axis.Z); }
                var flagsMoved = new bool[moved.Length / 3];
                ObservedPoints.Mark(moved, flagsMoved, frame.CameraToWorld, depth, w, h, train.Focal(w), w / 2.0, h / 2.0, 0.012, 0);
                Facing(moved, flagsMoved, out var movedSeen);
                Assert.That(movedSeen, Is.LessThan(0.05 * facingCount));
            }
        }

        [Test]
        public void AnOutFolderWithSomeoneElsesFilesIsRefusedBeforeAnythingIsWritten()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H, mesh: false);
                var renders = temp.Combine("plain");
                Directory.CreateDirectory(renders);
                for (var i = 0; i < views.Count; i++)
                    File.WriteAllBytes(Path.Combine(renders, "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 4), W, H, PngPixelFormat.Rgb8));
                var options = Options(dataset, renders);
                options.OutFolder = temp.Combine("out");
                Directory.CreateDirectory(options.OutFolder);
                File.WriteAllText(Path.Combine(options.OutFolder, "notes.txt"), "mine");
                Assert.That(() => RenderEvaluator.Run(options), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("notes.txt"));
                Assert.That(Directory.GetFileSystemEntries(options.OutFolder), Has.Length.EqualTo(1));

                // An earlier evaluation's folder is replaced; inside the dataset is refused.
                File.Delete(Path.Combine(options.OutFolder, "notes.txt"));
                RenderEvaluator.Run(options);
                RenderEvaluator.Run(options);
                Assert.That(Directory.GetFiles(Path.Combine(options.OutFolder, "errors")), Has.Length.EqualTo(3));
                options.OutFolder = Path.Combine(dataset, "evaluation");
                Assert.That(() => RenderEvaluator.Run(options), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("inside the dataset"));
                Assert.That(Directory.Exists(options.OutFolder), Is.False);

                // A transparent ground truth with --background dataset is refused (no colour recorded).
                options.OutFolder = temp.Combine("out2");
                options.Background = "dataset";
                Assert.That(() => RenderEvaluator.Run(options), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("transparent"));

                // --geometry without a geometry pack or --gt-mesh says what to pass.
                options.Background = "white";
                options.OutFolder = temp.Combine("out3");
                options.GeometryPath = Path.Combine(renders, "r_0.png");
                File.WriteAllText(temp.Combine("recon.ply"), "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 1\n");
                options.GeometryPath = temp.Combine("recon.ply");
                Assert.That(() => RenderEvaluator.Run(options), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("--gt-mesh"));
            }
        }

        [Test]
        public void AFileFoundBadWhileScoringLeavesNoOutputBehind()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, W, H, mesh: false);
                // nerfstudio renders whose last raw depth array has the wrong shape: found only when that view is scored.
                var output = temp.Combine("renders");
                for (var i = 0; i < views.Count; i++)
                {
                    Directory.CreateDirectory(Path.Combine(output, "test", "rgb"));
                    Directory.CreateDirectory(Path.Combine(output, "test", "raw-depth"));
                    File.WriteAllBytes(Path.Combine(output, "test", "rgb", "r_" + i + ".png"), PngWriter.Encode(AnalyticSphereDataset.Render(views[i], W, H, 2), W, H, PngPixelFormat.Rgb8));
                    var rows = i == 2 ? H / 2 : H;
                    NpyReaderTests.WriteNpyGz(Path.Combine(output, "test", "raw-depth", "r_" + i + ".npy.gz"), new[] { rows, W, 1 }, views[i].Depth.Take(rows * W).Select(d => d / 1000f).ToArray());
                }
                var options = Options(dataset, output);
                options.Threads = 1;
                Assert.That(() => RenderEvaluator.Run(options), Throws.TypeOf<InvalidParameterException>().With.Message.Contains("r_2.npy.gz").And.Message.Contains("(20, 48, 1)"));
                Assert.That(Directory.Exists(Path.Combine(output, "evaluation-test")), Is.False, "the error maps of views 0 and 1 are gone with the folder");

                // With the array fixed the same folder evaluates, depth scored from the arrays.
                NpyReaderTests.WriteNpyGz(Path.Combine(output, "test", "raw-depth", "r_2.npy.gz"), new[] { H, W, 1 }, views[2].Depth.Select(d => d / 1000f).ToArray());
                var result = RenderEvaluator.Run(options);
                Assert.That(result.Renders.Layout, Is.EqualTo(RenderLayout.Nerfstudio));
                Assert.That(result.Views.Select(v => v.Depth.AbsRel), Is.All.LessThan(1e-9), "the arrays hold the ground truth's depth");
            }
        }

        /// <summary>
        /// 3DGS render.py (182afc9) lines 41–43: with --train_test_exp each render is columns W//2 … W − 1 only. Such
        /// renders are scored against the same columns of the dataset's image and mask, figures computed here from them.
        /// </summary>
        [Test]
        public void ThreeDgsRightHalfRendersOfTrainTestExpAreScoredOnThatHalf()
        {
            using (var temp = new TempFolder())
            {
                const int w = 47; // odd: the half is 24 columns from column 23, as rendering[..., W // 2:] slices
                var dataset = temp.Combine("sphere");
                var views = AnalyticSphereDataset.Write(dataset, w, H);
                var renders = Path.Combine(temp.Combine("model"), "test", "ours_7000", "renders");
                Directory.CreateDirectory(renders);
                const int first = w / 2, half = w - w / 2;
                byte[] Right(byte[] rgb)
                {
                    var cut = new byte[half * H * 3];
                    for (var y = 0; y < H; y++) Buffer.BlockCopy(rgb, (y * w + first) * 3, cut, y * half * 3, half * 3);
                    return cut;
                }
                for (var i = 0; i < views.Count; i++)
                    File.WriteAllBytes(Path.Combine(renders, i.ToString("00000") + ".png"), PngWriter.Encode(Right(AnalyticSphereDataset.Render(views[i], w, H, 12)), half, H, PngPixelFormat.Rgb8));

                var result = RenderEvaluator.Run(Options(dataset, temp.Combine("model")));
                Assert.That(result.Renders.Layout, Is.EqualTo(RenderLayout.GaussianSplatting));
                Assert.That(result.Notes, Has.Some.Contains("right half").And.Some.Contains("column 23"));
                for (var i = 0; i < views.Count; i++)
                {
                    var truth = Right(AnalyticSphereDataset.Render(views[i], w, H, 0)).Select(b => b / 255f).ToArray();
                    var render = Right(AnalyticSphereDataset.Render(views[i], w, H, 12)).Select(b => b / 255f).ToArray();
                    double sum = 0, inside = 0, insideCount = 0;
                    for (var k = 0; k < truth.Length; k++)
                    {
                        double d = render[k] - truth[k];
                        sum += d * d;
                        var pixel = k / 3;
                        if (views[i].Mask[(pixel / half) * w + first + pixel % half] == 255) { inside += d * d; insideCount++; }
                    }
                    Assert.That((result.Views[i].Width, result.Views[i].Height), Is.EqualTo((half, H)));
                    Assert.That(result.Views[i].Psnr, Is.EqualTo(-10 * Math.Log10(sum / truth.Length)).Within(1e-9));
                    Assert.That(result.Views[i].MaskedPsnr, Is.EqualTo(-10 * Math.Log10(inside / insideCount)).Within(1e-9));
                    Assert.That(result.Views[i].Ssim, Is.EqualTo(ImageMetricsTests.Direct3dgs(render, truth, half, H, 3)).Within(1e-6));
                }
            }
        }

        [Test]
        public void EveryViewOfAnotherSizeIsCountedTheFirstFiveNamedInFrameOrder()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                AnalyticSphereDataset.Write(dataset, W, H, test: 8, mesh: false);
                var renders = temp.Combine("plain");
                for (var i = 0; i < 8; i++) TestPng.Write(Path.Combine(renders, "r_" + i + ".png"), W / 2, H / 2, 8, PngInfo.ColorTypeRgb);
                var message = Assert.Throws<InvalidParameterException>(() => RenderEvaluator.Run(Options(dataset, renders))).Message;
                for (var i = 0; i < 5; i++) Assert.That(message, Does.Contain("r_" + i + ".png: is 24×20 but the ground truth ./test/r_" + i + " is 48×40"));
                Assert.That(message, Does.Not.Contain("r_5.png"));
                Assert.That(message, Does.Contain("has 3 more view(s) like these (8 of 8 in all)"));
            }
        }

        [Test]
        public void RendersOfAnotherSizeAreRefused()
        {
            using (var temp = new TempFolder())
            {
                var dataset = temp.Combine("sphere");
                AnalyticSphereDataset.Write(dataset, W, H, mesh: false);
                var renders = temp.Combine("plain");
                for (var i = 0; i < 3; i++) TestPng.Write(Path.Combine(renders, "r_" + i + ".png"), W / 2, H / 2, 8, PngInfo.ColorTypeRgb);
                Assert.That(() => RenderEvaluator.Run(Options(dataset, renders)),
                    Throws.TypeOf<InvalidParameterException>().With.Message.Contains("is 24×20 but the ground truth ./test/r_0 is 48×40"));
                Assert.That(Directory.Exists(Path.Combine(renders, "evaluation-test")), Is.False);
            }
        }
    }
}
