using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The real nerf_synthetic lego cameras (transforms_train.json: poses and camera_angle_x only, no depth, normals or
    /// masks, as nerf_synthetic's train split) with analytic RGBA images rendered at its poses through NeRF's ray formula:
    /// the check passes, skipping what needs the missing files, one line each.
    /// </summary>
    [TestFixture]
    public class LegoCheckTests
    {
        [Test]
        public void LegoPassesWithItsSkips()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("lego");
                Directory.CreateDirectory(Path.Combine(folder, "train"));
                File.Copy(Fixtures.LegoTrainPath, Path.Combine(folder, "transforms_train.json"));
                var json = JObject.Parse(File.ReadAllText(Fixtures.LegoTrainPath));
                var angle = (double)json["camera_angle_x"];
                var scene = AnalyticScene.Layout(SceneNormalisation.Identity, Vector3d.Zero);
                foreach (JObject frame in json["frames"])
                {
                    var rows = frame["transform_matrix"].ToObject<double[][]>();
                    var png = PngWriter.Encode(Render(scene, rows, angle, 64, 64), 64, 64, PngPixelFormat.Rgba8);
                    File.WriteAllBytes(Path.Combine(folder, ((string)frame["file_path"]).Substring(2) + ".png"), png);
                }

                var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
                var text = string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems);
                TestContext.WriteLine(text);
                Assert.That(report.Failed, Is.False, text);
                Assert.That(report.ViewsChecked, Is.EqualTo(100));
                Assert.That(report.Results.Single(r => r.Name == "alpha vs mask").Status, Is.EqualTo(DatasetCheckStatus.Passed), text);
                foreach (var name in new[] { "depth vs mask", "depth vs normals", "multi-view geometry", "point cloud vs masks", "colour vs geometry" })
                {
                    var result = report.Results.Single(r => r.Name == name);
                    Assert.That(result.Status, Is.EqualTo(DatasetCheckStatus.Skipped), name);
                    Assert.That(result.SummaryLine, Does.StartWith(name + ": skipped ("), name);
                }
            }
        }

        /// <summary>Straight-alpha RGBA: coverage of 2×2 samples through NeRF's rays, the first surface's colour.</summary>
        static byte[] Render(AnalyticScene scene, double[][] c2w, double angle, int w, int h)
        {
            var rgba = new byte[w * h * 4];
            for (var y = 0; y < h; y++)
                for (var x = 0; x < w; x++)
                {
                    int covered = 0;
                    double[] colour = null;
                    for (var s = 0; s < 4; s++)
                    {
                        NerfRays.Ray(c2w, angle, w, h, x + 0.25 + 0.5 * (s & 1), y + 0.25 + 0.5 * (s >> 1), out var o, out var d);
                        if (!scene.Trace(new Vector3d(o[0], o[1], o[2]), new Vector3d(d[0], d[1], d[2]), 0, out _, out _, out var c, out _)) continue;
                        covered++;
                        colour = c;
                    }
                    if (covered == 0) continue;
                    var p = (y * w + x) * 4;
                    for (var c = 0; c < 3; c++) rgba[p + c] = (byte)(255 * colour[c]);
                    rgba[p + 3] = (byte)(covered * 255 / 4);
                }
            return rgba;
        }
    }
}
