using System;
using System.IO;
using System.Runtime.CompilerServices;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Documentation~/images/flow-example.png is what a capture with flow writes: an analytic monocular capture (the
    /// opaque sphere moves, the camera moves), its first train view, the forward flow to the next frame in the
    /// Middlebury colours (<see cref="FlowColours"/>), and where that flow's points are hidden (red) or outside the next
    /// image (blue) — all read back from the dataset's own files. After a deliberate change, rewrite the file with
    /// <c>NERF_DATASET_WRITE_DOC_IMAGES=1 dotnet test Tests/Core.Tests --filter "FullyQualifiedName~FlowPicture"</c>.
    /// </summary>
    [TestFixture]
    public class FlowPictureTests
    {
        const int Width = 240, Height = 180, Gap = 8, Label = 22;

        [Test]
        public void TheDocumentationPictureIsWhatTheCaptureWrites()
        {
            RgbCanvas canvas;
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "flow", new AnalyticDataset.Options
                {
                    Width = Width, Height = Height, Supersampling = 1, Train = 20, Val = 1, Test = 1, TimeSteps = 20, Monocular = true, PointCloud = 0,
                    MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
                    Configure = s => { s.Flow.On = true; s.Flow.Backward = false; s.Flow.SceneFlow = false; },
                });
                var record = FlowRecord.Read(folder);
                var pair = record.Pairs[0];
                Assert.That((pair.From, pair.To), Is.EqualTo((0, 1)));
                var flow = FloFile.Read(Path.Combine(folder, pair.FlowFile), out var w, out var h);
                var occluded = PngReader.Read(Path.Combine(folder, pair.OccludedFile)).Samples;
                var outside = PngReader.Read(Path.Combine(folder, pair.OutsideFile)).Samples;
                var image = PngReader.Read(Path.Combine(folder, record.Videos[0].Frames[0].Image.Replace('/', Path.DirectorySeparatorChar)));
                var state = new byte[w * h];
                for (var p = 0; p < state.Length; p++)
                    state[p] = (byte)(float.IsNaN(flow[2 * p]) ? FlowState.NoSurface : occluded[p] != 0 ? FlowState.Hidden : outside[p] != 0 ? FlowState.OutsideImage : FlowState.Visible);
                Assert.That(Array.IndexOf(state, (byte)FlowState.Hidden), Is.GreaterThanOrEqualTo(0), "the picture shows hidden points");

                canvas = new RgbCanvas(3 * Width + 2 * Gap, Height + Label, new byte[] { 255, 255, 255 });
                var colour = new byte[3 * w * h];
                for (var p = 0; p < w * h; p++)
                    for (var c = 0; c < 3; c++)
                    {
                        // The view's straight-alpha RGBA over white.
                        int a = image.Samples[4 * p + 3], v = image.Samples[4 * p + c];
                        colour[3 * p + c] = (byte)((v * a + 255 * (255 - a) + 127) / 255);
                    }
                Panel(canvas, 0, colour, "FRAME 0");
                Panel(canvas, Width + Gap, FlowColours.Picture(flow, w, h), "FLOW 0 TO 1");
                Panel(canvas, 2 * (Width + Gap), FlowColours.Occlusion(state, w, h), "OCCLUSION AT 1");
            }

            var path = Path.Combine(RepositoryRoot(), "Documentation~", "images", "flow-example.png");
            if (Environment.GetEnvironmentVariable("NERF_DATASET_WRITE_DOC_IMAGES") == "1")
            {
                File.WriteAllBytes(path, PngWriter.Encode(canvas.Pixels, canvas.Width, canvas.Height, PngPixelFormat.Rgb8));
                TestContext.WriteLine("wrote " + path);
            }
            var committed = PngReader.Decode(File.ReadAllBytes(path), path);
            Assert.That(new[] { committed.Width, committed.Height, committed.Channels }, Is.EqualTo(new[] { canvas.Width, canvas.Height, 3 }), path);
            var worst = 0;
            for (var p = 0; p < canvas.Pixels.Length; p++) worst = Math.Max(worst, Math.Abs(canvas.Pixels[p] - committed.Samples[p]));
            Assert.That(worst, Is.LessThanOrEqualTo(1), path + " no longer shows what the capture writes; rewrite it with NERF_DATASET_WRITE_DOC_IMAGES=1 (see this test's summary).");
        }

        static void Panel(RgbCanvas canvas, int left, byte[] rgb, string label)
        {
            var pixel = new byte[3];
            for (var y = 0; y < Height; y++)
                for (var x = 0; x < Width; x++)
                {
                    Array.Copy(rgb, 3 * (y * Width + x), pixel, 0, 3);
                    canvas.Set(left + x, Label + y, pixel);
                }
            canvas.Text(left + 4, 4, label, new byte[] { 20, 20, 20 });
        }

        static string RepositoryRoot([CallerFilePath] string path = "")
        {
            var folder = Path.GetDirectoryName(path);
            while (folder != null && !Directory.Exists(Path.Combine(folder, "Documentation~"))) folder = Path.GetDirectoryName(folder);
            return folder ?? throw new DirectoryNotFoundException("Documentation~ above " + path);
        }
    }
}
